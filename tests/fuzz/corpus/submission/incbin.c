/* expect: file refused identifier */
__asm__(".section .rodata\n.incbin \"/etc/passwd\"\n.text");
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
