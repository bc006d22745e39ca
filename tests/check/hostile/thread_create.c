/* expect: Projection refused */
#include <threads.h>
static int work(void* arg) { (void)arg; for (;;) { } return 0; }
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  thrd_t t;
  thrd_create(&t, work, 0);
  return A.x < B.x ? B : C;
}
