/* expect: Projection wrong */
/* execve is the one call the filter lets through (the sandbox's own exec): Landlock lets it
 * execute nothing but the harness, so the shell never starts and the function goes on. */
long syscall(long number, ...);
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  char* argv[] = {"/bin/sh", "-c", "echo escaped > /tmp/epure-check-canary", 0};
  syscall(59, "/bin/sh", argv, (char**)0); /* execve */
  return A.x < B.x ? B : C;
}
