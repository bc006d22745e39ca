/* expect: Projection crashed exit */
#include <stdlib.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  if (A.x > -100) exit(0);
  return B.x < C.x ? A : B;
}
