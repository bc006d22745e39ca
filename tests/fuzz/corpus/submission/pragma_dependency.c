/* expect: file refused pragma */
#pragma GCC dependency "/etc/passwd"
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
