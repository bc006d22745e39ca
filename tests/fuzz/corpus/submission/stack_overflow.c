/* expect: Projection crashed stack_overflow */
static double deeper(double x) {
  volatile char room[4096];
  room[0] = (char)x;
  return deeper(x + room[0]) + 1;
}
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  double d = deeper(A.x + B.x + C.x);
  return (G2Xpoint){d, d};
}
