/* expect: Projection refused clock_nanosleep */
#include <time.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  struct timespec t = {1, 0};
  nanosleep(&t, 0);
  return A.x < B.x ? B : C;
}
