#pragma once
// What produced a file: the resolved parfile, the thorn list, the git revision, the build type.
// Written into every HDF5 output and checkpoint as /provenance.
#include <hdf5.h>

#include <string>

namespace remnant {
class Context;
}

namespace remnant::io {

struct Provenance {
  std::string parfile;
  std::string thorns;  // comma separated, activation order
  std::string git_revision;
  std::string build_type;
};

Provenance provenance_of(const Context& ctx);
// Creates group /provenance in `file` (collective for a parallel file); rank 0 writes the text.
void write_provenance(hid_t file, const Provenance& p, bool writer);

}  // namespace remnant::io
