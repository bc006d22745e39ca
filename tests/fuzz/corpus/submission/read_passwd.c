/* expect: Projection refused openat */
#include <stdio.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  FILE* f = fopen("/etc/passwd", "r");
  char line[256] = "";
  if (f && fgets(line, sizeof line, f)) printf("%s", line);
  return A.x < B.x ? B : C;
}
