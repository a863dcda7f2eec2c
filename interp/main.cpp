// igds: Interactive Design of Interpolated Surfaces.
#include "interp/start.h"

int main(int argc, char** argv) {
  return igds::igds_main(argc, argv);
}
