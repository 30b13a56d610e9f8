#include "provenance.hpp"

#include "h5.hpp"
#include "remnant/build_info.hpp"
#include "remnant/context.hpp"

namespace remnant::io {

Provenance provenance_of(const Context& ctx) {
  Provenance p;
  p.parfile = ctx.resolved_parfile();
  for (const auto& t : ctx.active_thorns()) p.thorns += (p.thorns.empty() ? "" : ",") + t;
  p.git_revision = git_revision();
  p.build_type = build_type();
  return p;
}

void write_provenance(hid_t file, const Provenance& p, bool writer) {
  h5::Handle g = h5::create_group(file, "provenance");
  h5::write_string(g, "parfile", p.parfile, writer);
  h5::write_string(g, "thorns", p.thorns, writer);
  h5::write_attr(g, "git_revision", p.git_revision);
  h5::write_attr(g, "build_type", p.build_type);
  h5::write_attr(file, "git_revision", p.git_revision);
  h5::write_attr(file, "build_type", p.build_type);
}

}  // namespace remnant::io
