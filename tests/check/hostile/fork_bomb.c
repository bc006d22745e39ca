/* expect: Projection refused */
/* A fork bomb: the filter stops the first fork (clone), and RLIMIT_NPROC is 0 besides. */
int fork(void);
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  for (;;) fork();
  return A.x < B.x ? B : C;
}
