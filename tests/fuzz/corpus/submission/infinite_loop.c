/* expect: Projection timeout */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  volatile double x = A.x;
  for (;;) x = x * 1.0000001 + B.x - C.x;
  return A;
}
