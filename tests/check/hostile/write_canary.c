/* expect: Projection refused openat */
/* Writing a file: the canary the test watches. */
#include <stdio.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  FILE* f = fopen("/tmp/epure-check-canary", "w");
  if (f) fputs("overwritten\n", f);
  remove("/tmp/epure-check-canary");
  return A.x < B.x ? B : C;
}
