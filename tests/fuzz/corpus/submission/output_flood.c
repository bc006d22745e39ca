/* expect: Projection refused output */
/* A gigabyte of output: stopped past 1 MiB. */
#include <stdio.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  for (long i = 0; i < (1L << 30) / 64; ++i) printf("%-63s\n", "all work and no play makes Jack a dull boy");
  return A.x < B.x ? B : C;
}
