/* expect: Projection refused protocol */
/* Bytes on the checker's result pipe (fd 3), to forge "right" answers. */
long syscall(long number, ...);
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  char forged[56] = "R all right, trust me";
  syscall(1, 3, forged, sizeof forged); /* write(3, ...) */
  return A.x < B.x ? B : C;
}
