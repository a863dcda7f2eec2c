// igds: Interactive Design of Interpolated Surfaces.
#include "interp/start.h"
#include "workspace/kernels/interrupt.h"

int main(int argc, char** argv) {
  // Before any thread exists: no thread of igds may be ended by Ctrl-C
  // (workspace/kernels/interrupt.h).
  igds::block_interrupts();
  return igds::igds_main(argc, argv);
}
