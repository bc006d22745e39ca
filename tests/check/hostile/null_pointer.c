/* expect: Projection crashed SIGSEGV */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  G2Xpoint* nowhere = 0;
  if (A.x > -1000) return *nowhere;
  return B.x < C.x ? B : C;
}
