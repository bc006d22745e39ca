/* expect: Projection crashed SIGSEGV */
/* Memory without end: past RLIMIT_AS (256 MiB) malloc returns NULL, and the write through it faults. */
#include <stdlib.h>
G2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C) {
  char* volatile block;
  void* volatile* chain = 0;
  while ((block = malloc(1 << 24)) != NULL) {
    *(void* volatile*)block = (void*)chain; /* kept: nothing to optimise away */
    chain = (void* volatile*)block;
  }
  *(volatile char*)block = 1; /* block is NULL here */
  return B.x < C.x ? A : B;
}
