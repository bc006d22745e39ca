/* expect: file compile_error */
/* asm spelled by token pasting, which the scan cannot see: the assembler then finds no
 * /etc/passwd to read (Landlock: the compiler sees /usr and its own directory only). */
#define CAT(a, b) a##b
CAT(__as, m__)(".section .rodata\nsecret: .incbin \"/etc/passwd\"\n.text");
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) { return A.x < B.x ? B : C; }
