// remnant-genviews <thorn.yaml> <header> [shown path]: writes the named-view header of a thorn. The header is
// rewritten only when its text changes, so that a rebuilt tool does not recompile every thorn.
#include <fstream>
#include <iostream>
#include <sstream>

#include "remnant/view_codegen.hpp"

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::cerr << "usage: remnant-genviews <thorn.yaml> <output header> [path shown in the header]\n";
    return 2;
  }
  try {
    std::ifstream in(argv[1]);
    if (!in) throw std::runtime_error(std::string("cannot read ") + argv[1]);
    std::stringstream text;
    text << in.rdbuf();
    const std::string header = remnant::generate_view_header(remnant::parse_thorn_spec(text.str(), argc == 4 ? argv[3] : argv[1]));
    std::ifstream old(argv[2]);
    std::stringstream old_text;
    if (old) old_text << old.rdbuf();
    if (!old || old_text.str() != header) {
      std::ofstream out(argv[2], std::ios::trunc);
      out << header;
      if (!out) throw std::runtime_error(std::string("cannot write ") + argv[2]);
    }
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
