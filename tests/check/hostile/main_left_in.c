/* expect: Projection passed */
/* A main() of the student's own, which must not run: it is renamed away when checked. */
#include <stdio.h>
#include <stdlib.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  G2Xvector AB = g2x_SetVect(A, B), AC = g2x_SetVect(A, C);
  double t = g2x_ProdScal(AB, AC) / g2x_ProdScal(AB, AB);
  return (G2Xpoint){A.x + t * AB.x, A.y + t * AB.y};
}
int main(void) {
  FILE* f = fopen("/tmp/epure-check-canary", "w");
  if (f) fputs("main ran\n", f);
  abort();
}
