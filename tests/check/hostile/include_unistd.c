/* expect: file refused include */
#include <unistd.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { fork(); return A.x < B.x ? B : C; }
