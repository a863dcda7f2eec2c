// igds: Interactive Design of Interpolated Surfaces.
#include <malloc.h>

#include "interp/start.h"

int main(int argc, char** argv) {
  // Memory a command frees stays in igds for the next command instead of going back to the
  // system: a DISPLAY, PLOT or EXPORT of 4 M points uses hundreds of megabytes of scratch, and
  // every fresh page costs a fault and its clearing (docs/decisions.md, "Memory kept").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: blocks below it come from the heap
  mallopt(M_MMAP_MAX, 0);               // and the larger ones too (an image of 64 MB, INTPN)
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  return igds::igds_main(argc, argv);
}
