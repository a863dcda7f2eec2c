// Starting igds (manual 2.1: INIT and START): the command line, the disk and its lock, the
// saved session, then the conversation on the command files and the terminal.
#pragma once

namespace igds {

// The whole program; returns the exit status (docs/interp.md, "Command line").
int igds_main(int argc, char** argv);

}  // namespace igds
