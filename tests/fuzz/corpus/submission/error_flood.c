/* expect: file compile_error */
#define E10 x x x x x x x x x x
#define E100 E10 E10 E10 E10 E10 E10 E10 E10 E10 E10
#define E1000 E100 E100 E100 E100 E100 E100 E100 E100 E100 E100
int f(void) { E1000 E1000 E1000 E1000 E1000 }
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
