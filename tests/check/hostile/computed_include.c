/* expect: file refused include */
#define SECRET "/etc/shadow"
#include SECRET
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
