/* expect: Projection refused kill */
/* A signal to the parent: the checker. */
long syscall(long number, ...);
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  long parent = syscall(110); /* getppid */
  syscall(62, parent, 9);     /* kill(parent, SIGKILL) */
  return A.x < B.x ? B : C;
}
