/* expect: Projection refused socket */
int socket(int domain, int type, int protocol);
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  int s = socket(2, 1, 0); /* AF_INET, SOCK_STREAM */
  return s >= 0 ? A : (A.x < B.x ? B : C);
}
