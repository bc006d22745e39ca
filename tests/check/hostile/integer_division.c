/* expect: Projection crashed SIGFPE */
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  volatile int zero = 0;
  int n = (int)A.x / zero;
  return (G2Xpoint){n + B.x, C.y};
}
