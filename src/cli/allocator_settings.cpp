// jemalloc's settings, read by the allocator at its first call (jemalloc's `malloc_conf`
// symbol; the environment's MALLOC_CONF still overrides it).
//
// Why: jemalloc keeps pages it freed ("dirty") for 10 s by default before it gives them back to
// the system. A set's drawing frees memory as fast as it allocates it, so the resident size of a
// short run grew with its length until the 10 s window was full: --format svg went from 42 MB at
// 1,000 sheets to 71 MB at 4,000, without a byte held by the program (issue 37). With dirty pages
// returned after 1 s and no "muzzy" stage, the same runs take 45 MB and 43 MB, in the same CPU
// time (bench/README.md, "Memory"). 1 s still let a short run's peak swing by a fifth with the
// machine's load (300 SVG sheets 42–54 MB); after 200 ms it holds at 44 MB, and the CPU time
// of the default mode is the same within the runs' spread.
extern "C" {
extern const char* malloc_conf;
const char* malloc_conf = "dirty_decay_ms:200,muzzy_decay_ms:0";
}
