/* expect: Projection refused openat */
/* Code that runs before main(): under the sandbox already. */
#include <stdio.h>
__attribute__((constructor)) static void early(void) {
  FILE* f = fopen("/etc/passwd", "r");
  if (f) fclose(f);
}
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
