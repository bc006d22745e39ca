/* expect: Projection crashed abort */
#include <assert.h>
#include <stdlib.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  assert(A.x == B.x && "points are never equal");
  abort();
  return C;
}
