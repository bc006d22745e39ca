/* expect: Projection timeout */
__attribute__((constructor)) static void early(void) {
  for (volatile int i = 0;; ++i) {
  }
}
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
