#include "remnant/view_codegen.hpp"

#include <cctype>
#include <set>
#include <sstream>

namespace remnant {
namespace {

// Names a generated accessor may not take: C++ keywords and GroupView's own members.
const std::set<std::string>& reserved_names() {
  static const std::set<std::string> names{
      "alignas", "alignof", "and", "asm", "auto", "bool", "break", "case", "catch", "char", "class", "const",
      "constexpr", "continue", "default", "delete", "do", "double", "else", "enum", "explicit", "export", "extern",
      "false", "float", "for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new",
      "noexcept", "not", "nullptr", "operator", "or", "private", "protected", "public", "register", "return",
      "short", "signed", "sizeof", "static", "struct", "switch", "template", "this", "throw", "true", "try",
      "typedef", "typename", "union", "unsigned", "using", "virtual", "void", "volatile", "while", "xor",
      // GroupView and the generated members
      "field", "group", "full_name", "ncomp", "idx", "id", "centering", "GroupView", "bind"};
  return names;
}

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

void check_name(const ThornSpec& spec, const VariableGroupSpec& g, const std::string& name, const char* what) {
  if (!is_identifier(name) || reserved_names().count(name))
    throw InputError(g.where, std::string(what) + " '" + name + "' of group " + spec.name + "::" + g.name +
                                  " cannot name a generated C++ accessor (a keyword, a view member or not an identifier)");
}

// The declared tensor a component belongs to: "vel" for vel1..vel3, "gamma" for gamma11..gamma33.
std::string tensor_base(const ComponentSpec& c) {
  const std::size_t digits = c.indices[1] >= 0 ? 2 : (c.indices[0] >= 0 ? 1 : 0);
  return c.name.substr(0, c.name.size() - digits);
}

// Whether the group holds every component of the tensor of component c (not just 'B[2]'): only
// then does the tensor get an indexed accessor.
bool whole_tensor(const VariableGroupSpec& g, const ComponentSpec& c) {
  int n = 0;
  for (const auto& o : g.components) n += o.indices[0] >= 0 && tensor_base(o) == tensor_base(c);
  return n == component_count(c.kind);
}

void emit_group(std::ostringstream& os, const ThornSpec& spec, const VariableGroupSpec& g) {
  check_name(spec, g, g.name, "group");
  const std::string full = spec.name + "::" + g.name;
  os << "// " << full << " (" << to_string(g.centering) << "): " << g.description << "\n";
  os << "struct " << g.name << " : GroupView {\n";
  os << "  static constexpr const char* full_name = \"" << full << "\";\n";
  os << "  static constexpr int ncomp = " << g.ncomp() << ";\n";
  os << "  static constexpr Centering centering = Centering::" << to_string(g.centering) << ";\n";
  // Component indices, and the first component of every declared vector or tensor.
  os << "  struct idx {\n    enum : int {";
  for (int c = 0; c < g.ncomp(); ++c) {
    check_name(spec, g, g.components[static_cast<std::size_t>(c)].name, "component");
    os << (c ? ", " : " ") << g.components[static_cast<std::size_t>(c)].name << " = " << c;
  }
  os << " };\n";
  std::set<std::string> seen;
  for (int c = 0; c < g.ncomp(); ++c) {
    const ComponentSpec& comp = g.components[static_cast<std::size_t>(c)];
    if (comp.indices[0] < 0 || !whole_tensor(g, comp)) continue;
    const std::string base = tensor_base(comp);
    if (!seen.insert(base).second) continue;
    check_name(spec, g, base, "tensor");
    os << "    static constexpr int " << base << " = " << c << ";\n";
  }
  os << "  };\n";
  os << "  " << g.name << "() = default;\n";
  os << "  " << g.name << "(Block& b, int group_id) : GroupView(b, group_id, ncomp) {}\n";
  os << "  " << g.name << "(const Context& ctx, Block& b) : GroupView(ctx, b, full_name, ncomp) {}\n";
  os << "  static int id(const Context& ctx) { return ctx.var(full_name); }\n";
  seen.clear();
  for (int c = 0; c < g.ncomp(); ++c) {
    const ComponentSpec& comp = g.components[static_cast<std::size_t>(c)];
    os << "  double& " << comp.name << "(int i, int j, int k) const { return (*this)(" << c << ", i, j, k); }\n";
    if (comp.indices[0] < 0 || !whole_tensor(g, comp)) continue;
    const std::string base = tensor_base(comp);
    if (!seen.insert(base).second) continue;
    if (comp.indices[1] < 0)
      os << "  double& " << base << "(int a, int i, int j, int k) const { return (*this)(idx::" << base
         << " + a, i, j, k); }\n";
    else
      os << "  double& " << base << "(int a, int b, int i, int j, int k) const { return (*this)(idx::" << base
         << " + symmetric_index(a, b), i, j, k); }\n";
  }
  os << "};\n\n";
}

}  // namespace

std::string generate_view_header(const ThornSpec& spec) {
  std::ostringstream os;
  os << "// Generated by remnant-genviews from " << spec.yaml_path << "; do not edit.\n";
  os << "#pragma once\n#include <remnant/group_view.hpp>\n\n";
  os << "namespace remnant::vars::" << spec.name << " {\n\n";
  for (const auto& g : spec.variables) emit_group(os, spec, g);
  os << "}  // namespace remnant::vars::" << spec.name << "\n";
  return os.str();
}

}  // namespace remnant
