// jemalloc's settings for sculpt-cli, read by jemalloc before the first allocation (its
// manual, "malloc_conf"); the MALLOC_CONF environment variable still overrides them.
//
// thp:always asks the kernel for transparent huge pages for every mapping jemalloc makes, its
// own metadata included. A scene's build touches hundreds of megabytes once; in 2 MB pages it
// takes a fiftieth of the page faults, which on some virtual machines were half the time of the
// first step (docs/memory.md).
extern "C" {
extern const char* malloc_conf;
const char* malloc_conf = "thp:always,metadata_thp:always";
}
