/* The harness of `epure check`: the main() linked with a student's file. It reads cases from
 * file descriptor 0, calls the student's functions, and writes what they return on file
 * descriptor 3 (the student's own output, on 1 and 2, goes to a pipe the checker drains apart).
 *
 * It runs confined (src/check/sandbox.h): the seccomp filter and the Landlock rules were set
 * before this program was executed, so they hold from its first instruction, constructors and
 * ifunc resolvers included. Any system call the filter does not allow raises SIGSYS; the handler
 * below says which on fd 3 and ends the process. Fatal signals are said the same way.
 *
 * The records are the fixed-size ones of src/check/protocol.h (native byte order: both ends run
 * on the same machine). Every symbol of its own is static or prefixed epure_harness_, so that a
 * student's names cannot collide with them. */
#define _GNU_SOURCE
#include <setjmp.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <ucontext.h>
#include <unistd.h>

#include "raytracer.h"

/* A function the student's file does not define is a null pointer. */
#pragma weak Projection
#pragma weak InterSegments
#pragma weak rayon_inter_cercle
#pragma weak rayon_inter_cercle_canonique
#pragma weak rayon_inter_carre_canonique
#pragma weak rayon_inter_ellipse
#pragma weak rayon_inter_rectangle
#pragma weak rayon_inter_sphere
#pragma weak rayon_inter_cube_canonique

enum { kVersion = 1, kInputs = 10, kOutputs = 6, kFunctions = 9 };

/* parent -> harness */
struct case_record {
  uint8_t tag; /* 'C' a case, 'Q' the end */
  uint8_t fn;
  uint16_t reserved;
  uint32_t seq;
  double in[kInputs];
};
/* harness -> parent */
struct result_record {
  uint8_t tag; /* 'H' hello, 'R' result, 'N' not written, 'S' forbidden system call, 'K' a signal
                  raised, 'G' a fatal signal */
  uint8_t fn;
  uint8_t flag;
  uint8_t reserved;
  uint32_t seq;
  union {
    double out[kOutputs];
    int64_t word[kOutputs];
  } u;
};
_Static_assert(sizeof(struct case_record) == 88, "case record");
_Static_assert(sizeof(struct result_record) == 56, "result record");

static volatile int epure_harness_fn = 255; /* the function being called, 255 between calls */
static volatile uint32_t epure_harness_seq;
static sigjmp_buf epure_harness_todo;
static char* epure_harness_stack_top;
static uintptr_t epure_harness_stack_size;
static char epure_harness_alt_stack[1 << 16];
static char epure_harness_stdout[1 << 12];

/* Raw system calls only: these run in signal handlers too. */
static void epure_harness_send(const struct result_record* r) {
  const char* p = (const char*)r;
  size_t left = sizeof *r;
  while (left > 0) {
    long n = syscall(SYS_write, 3, p, left);
    if (n <= 0) syscall(SYS_exit_group, 120);
    p += n;
    left -= (size_t)n;
  }
}

static _Noreturn void epure_harness_end(int status) {
  syscall(SYS_exit_group, status);
  for (;;) {
  }
}

static void epure_harness_on_sigsys(int sig, siginfo_t* si, void* context) {
  (void)sig;
  ucontext_t* uc = (ucontext_t*)context;
  int64_t args[3] = {0, 0, 0};
#if defined(__x86_64__)
  args[0] = uc->uc_mcontext.gregs[REG_RDI];
  args[1] = uc->uc_mcontext.gregs[REG_RSI];
  args[2] = uc->uc_mcontext.gregs[REG_RDX];
#elif defined(__aarch64__)
  args[0] = (int64_t)uc->uc_mcontext.regs[0];
  args[1] = (int64_t)uc->uc_mcontext.regs[1];
  args[2] = (int64_t)uc->uc_mcontext.regs[2];
#else
  (void)uc;
#endif
  struct result_record r;
  memset(&r, 0, sizeof r);
  r.fn = (uint8_t)epure_harness_fn;
  r.seq = epure_harness_seq;
  const long nr = si->si_syscall;
  const long self = syscall(SYS_getpid);
  int raised = 0;
  /* kill(self or own group), tkill(self), tgkill(self, ...): a signal to itself (abort, raise) */
  if (nr == SYS_kill && (args[0] == self || args[0] == 0)) raised = (int)args[1];
  if (nr == SYS_tkill && args[0] == self) raised = (int)args[1];
  if (nr == SYS_tgkill && args[0] == self) raised = (int)args[2];
  if (raised > 0) {
    r.tag = 'K';
    r.u.word[0] = raised;
  } else {
    r.tag = 'S';
    r.u.word[0] = nr;
    r.u.word[1] = args[0];
    r.u.word[2] = args[1];
    r.u.word[3] = args[2];
  }
  epure_harness_send(&r);
  epure_harness_end(121);
}

static void epure_harness_on_fatal(int sig, siginfo_t* si, void* context) {
  (void)context;
  struct result_record r;
  memset(&r, 0, sizeof r);
  r.tag = 'G';
  r.fn = (uint8_t)epure_harness_fn;
  r.seq = epure_harness_seq;
  const uintptr_t addr = (uintptr_t)si->si_addr, top = (uintptr_t)epure_harness_stack_top;
  /* a fault just below the stack's lowest page: the stack ran out */
  if (sig == SIGSEGV && addr < top && top - addr < epure_harness_stack_size + (1u << 20)) r.flag = 1;
  r.u.word[0] = sig;
  r.u.word[1] = si->si_code;
  r.u.word[2] = (int64_t)addr;
  epure_harness_send(&r);
  epure_harness_end(122);
}

/* Runs before every constructor, the student's included (.preinit_array, in link order: this
 * file is linked first). The sandbox is already in force. */
static void epure_harness_preinit(void) {
  char here;
  epure_harness_stack_top = &here;
  struct rlimit stack;
  epure_harness_stack_size = getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY
                                 ? (uintptr_t)stack.rlim_cur
                                 : (uintptr_t)8 << 20;
  stack_t alt = {.ss_sp = epure_harness_alt_stack, .ss_size = sizeof epure_harness_alt_stack, .ss_flags = 0};
  sigaltstack(&alt, NULL);
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigfillset(&sa.sa_mask);
  sa.sa_sigaction = epure_harness_on_sigsys;
  sigaction(SIGSYS, &sa, NULL);
  sa.sa_sigaction = epure_harness_on_fatal;
  const int fatal[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP};
  for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; ++i) sigaction(fatal[i], &sa, NULL);
  /* a buffer of our own: stdio then never asks the system what stdout is */
  setvbuf(stdout, epure_harness_stdout, _IOFBF, sizeof epure_harness_stdout);
}
__attribute__((section(".preinit_array"), used)) static void (*epure_harness_preinit_entry)(void) =
    epure_harness_preinit;

_Noreturn void epure_todo(const char* function, ...) {
  (void)function;
  if (epure_harness_fn != 255) siglongjmp(epure_harness_todo, 1);
  /* outside any call of ours (a constructor): said as a fatal stop */
  struct result_record r;
  memset(&r, 0, sizeof r);
  r.tag = 'N';
  r.fn = 255;
  epure_harness_send(&r);
  epure_harness_end(123);
}

static const double kUnset = __builtin_nan("");

static G2Xpoint p2(const double* v) { return (G2Xpoint){v[0], v[1]}; }
static G3Xpoint p3(const double* v) { return (G3Xpoint){v[0], v[1], v[2]}; }

/* Calls function `fn` on `in`; fills the record's flag (the boolean returned) and outputs. */
static void epure_harness_call(int fn, const double* in, struct result_record* r) {
  G2Xpoint J = {kUnset, kUnset}, N = {kUnset, kUnset};
  G3Xpoint J3 = {kUnset, kUnset, kUnset}, N3 = {kUnset, kUnset, kUnset};
  bool hit = true;
  switch (fn) {
    case 0:
      J = Projection(p2(in), p2(in + 2), p2(in + 4));
      break;
    case 1:
      hit = InterSegments(p2(in), p2(in + 2), p2(in + 4), p2(in + 6), &J);
      break;
    case 2:
      hit = rayon_inter_cercle(&J, &N, p2(in), p2(in + 2), p2(in + 4), in[6]);
      break;
    case 3:
      hit = rayon_inter_cercle_canonique(&J, &N, p2(in), p2(in + 2));
      break;
    case 4:
      hit = rayon_inter_carre_canonique(&J, &N, p2(in), p2(in + 2));
      break;
    case 5:
      hit = rayon_inter_ellipse(&J, &N, p2(in), p2(in + 2), p2(in + 4), in[6], in[7], in[8]);
      break;
    case 6:
      hit = rayon_inter_rectangle(&J, &N, p2(in), p2(in + 2), p2(in + 4), in[6], in[7], in[8]);
      break;
    case 7:
      hit = rayon_inter_sphere(&J3, &N3, p3(in), p3(in + 3), p3(in + 6), in[9]);
      break;
    case 8:
      hit = rayon_inter_cube_canonique(&J3, &N3, p3(in), p3(in + 3));
      break;
  }
  r->flag = hit ? 1 : 0;
  if (fn == 7 || fn == 8) {
    const double out[6] = {J3.x, J3.y, J3.z, N3.x, N3.y, N3.z};
    memcpy(r->u.out, out, sizeof out);
  } else {
    const double out[6] = {J.x, J.y, N.x, N.y, 0, 0};
    memcpy(r->u.out, out, sizeof out);
  }
}

static int epure_harness_read(struct case_record* c) {
  char* p = (char*)c;
  size_t left = sizeof *c;
  while (left > 0) {
    long n = syscall(SYS_read, 0, p, left);
    if (n <= 0) return 0;
    p += n;
    left -= (size_t)n;
  }
  return 1;
}

int main(void) {
  void* const defined[kFunctions] = {
      (void*)Projection,          (void*)InterSegments,         (void*)rayon_inter_cercle,
      (void*)rayon_inter_cercle_canonique, (void*)rayon_inter_carre_canonique, (void*)rayon_inter_ellipse,
      (void*)rayon_inter_rectangle, (void*)rayon_inter_sphere,    (void*)rayon_inter_cube_canonique};
  struct result_record hello;
  memset(&hello, 0, sizeof hello);
  hello.tag = 'H';
  hello.seq = kVersion;
  for (int i = 0; i < kFunctions; ++i)
    if (defined[i]) hello.u.word[0] |= (int64_t)1 << i;
  epure_harness_send(&hello);

  struct case_record c;
  while (epure_harness_read(&c)) {
    if (c.tag != 'C' || c.fn >= kFunctions || !defined[c.fn]) break;
    struct result_record r;
    memset(&r, 0, sizeof r);
    r.fn = c.fn;
    r.seq = c.seq;
    epure_harness_seq = c.seq;
    epure_harness_fn = c.fn;
    if (sigsetjmp(epure_harness_todo, 0) == 0) {
      epure_harness_call(c.fn, c.in, &r);
      r.tag = 'R';
    } else {
      r.tag = 'N';
    }
    epure_harness_fn = 255;
    fflush(stdout);
    epure_harness_send(&r);
  }
  epure_harness_end(0);
}
