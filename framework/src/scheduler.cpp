#include "remnant/scheduler.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iomanip>
#include <limits>
#include <queue>
#include <set>
#include <sstream>

#include "remnant/comm_counters.hpp"
#include "yaml_util.hpp"

namespace remnant {

namespace {

using Clock = std::chrono::steady_clock;

// Variable groups an item touches; for a group, the union over everything inside it.
struct Access {
  std::set<int> reads, writes;
};

// in_off_group: the item sits (at any depth) in a schedule group whose fixed `if:` is false, so it
// cannot run either (a function may thus combine two conditions: its own and its group's).
std::vector<int> resolve_access(const VariableAccess& a, const ScheduleItem& item, const VariableRegistry& vars,
                                const Parameters& params, bool in_off_group = false) {
  const std::string& thorn = item.thorn;
  if (a.group == "@evolved") return vars.evolved();
  if (a.group == "@all") {
    std::vector<int> out;
    for (int g = 0; g < vars.size(); ++g) out.push_back(g);
    return out;
  }
  if (a.group.front() == '@' && a.group != "@rhs")
    throw InputError(a.where, "unknown pseudo-group '" + a.group + "'; allowed: @evolved, @rhs, @all");
  if (a.group == "@rhs") {
    std::vector<int> out;
    for (int id : vars.evolved()) out.push_back(vars.group(id).rhs_id);
    return out;
  }
  const int id = vars.find(a.group, thorn);
  if (id < 0) {
    // A group whose `if:` is false: fine for an item that cannot run in this run either.
    if (const VariableGroupSpec* off = vars.without_storage(a.group, thorn)) {
      const bool item_off = in_off_group || (!item.condition.empty() && !condition_is_steerable(item.condition, params) &&
                                             !condition_holds_now(item.condition, params, item.where));
      if (item_off) return {};
      throw InputError(a.where, "'" + item.name + "' accesses " + off->full_name() + ", which has no storage in this run " +
                                    "(its 'if: " + off->condition.text + "' is false); give '" + item.name +
                                    "' an 'if:' on a non-steerable parameter that is false whenever the group is absent");
    }
    std::vector<std::string> names;
    for (const auto& g : vars.groups()) names.push_back(g.full_name());
    std::string msg = "unknown variable group '" + a.group + "'";
    auto near = nearest_names(a.group.find("::") == std::string::npos ? thorn + "::" + a.group : a.group, names, 3);
    if (!near.empty()) msg += " (did you mean " + join(near) + "?)";
    throw InputError(a.where, msg + "; groups of active thorns: " + join(names));
  }
  return {id};
}

std::string item_label(const ScheduleItem& it) { return it.thorn + "::" + it.name; }

}  // namespace

Scheduler::Scheduler(const std::vector<const ThornSpec*>& thorns, const VariableRegistry& vars, const Parameters& params,
                     const ImplementationTable& impl)
    : ghosts_valid_(static_cast<std::size_t>(vars.size()), false), vars_(&vars) {
  std::map<std::string, const ScheduleItem*> groups;
  std::map<std::string, const ScheduleItem*> all_items;
  for (const ThornSpec* t : thorns) {
    for (const auto& it : t->schedule) {
      if (is_standard_bin(it.name))
        throw InputError(it.where, "'" + it.name + "' is the name of a schedule bin; choose another name");
      if (auto prev = all_items.find(it.name); prev != all_items.end())
        throw InputError(it.where, "'" + it.name + "' is scheduled by " + t->name + " and also by " +
                                       prev->second->thorn + " at " + prev->second->where.str() +
                                       "; scheduled names must be unique");
      all_items[it.name] = &it;
      if (it.is_group) groups[it.name] = &it;
    }
  }
  std::vector<std::string> containers = standard_bins();
  for (const auto& [name, g] : groups) containers.push_back(name);
  for (const ThornSpec* t : thorns) {
    for (const auto& it : t->schedule) {
      if (!is_standard_bin(it.in) && !groups.count(it.in)) {
        if (it.in_optional) continue;  // the hook's group belongs to an inactive thorn
        std::string msg = "'" + it.name + "' is scheduled in '" + it.in + "', which is neither a bin nor a group";
        auto near = nearest_names(it.in, containers, 3);
        if (!near.empty()) msg += " (did you mean " + join(near) + "?)";
        throw InputError(it.where, msg + "; bins: " + join(standard_bins()));
      }
      if (it.is_group && it.in == it.name) throw InputError(it.where, "group '" + it.name + "' is scheduled in itself");
      by_container_[it.in].push_back(&it);
    }
  }
  // Groups nested in a cycle (A in B, B in A) are never reached from a bin: report them.
  for (const auto& [name, g] : groups) {
    std::set<std::string> seen;
    std::string c = name;
    std::vector<std::string> path;
    while (!is_standard_bin(c)) {
      if (!seen.insert(c).second) throw InputError(g->where, "groups are nested in a cycle: " + join(path, " in ") + " in " + c);
      path.push_back(c);
      c = groups.at(c)->in;
    }
  }
  // Groups whose `if:` is fixed and false here, or that sit in such a group.
  for (const auto& [name, g] : groups) {
    for (const ScheduleItem* c = g; c; c = groups.count(c->in) ? groups.at(c->in) : nullptr)
      if (!c->condition.empty() && !condition_is_steerable(c->condition, params) &&
          !condition_holds_now(c->condition, params, c->where)) {
        off_groups_.insert(name);
        break;
      }
  }
  for (const auto& bin : standard_bins())
    bins_[bin] = build_container(bin, by_container_[bin], impl, vars, params, 0);
}

std::vector<ScheduleNode> Scheduler::build_container(const std::string& container, const std::vector<const ScheduleItem*>& items,
                                                     const ImplementationTable& impl, const VariableRegistry& vars,
                                                     const Parameters& params, int depth) {
  const std::size_t n = items.size();
  // Access sets, including everything nested inside groups.
  std::function<Access(const ScheduleItem*)> access_of = [&](const ScheduleItem* it) {
    Access a;
    for (const auto& r : it->reads)
      for (int id : resolve_access(r, *it, vars, params, off_groups_.count(it->in) > 0)) a.reads.insert(id);
    for (const auto& w : it->writes)
      for (int id : resolve_access(w, *it, vars, params, off_groups_.count(it->in) > 0)) a.writes.insert(id);
    if (it->is_group)
      for (const ScheduleItem* child : by_container_[it->name]) {
        Access c = access_of(child);
        a.reads.insert(c.reads.begin(), c.reads.end());
        a.writes.insert(c.writes.begin(), c.writes.end());
      }
    return a;
  };
  std::vector<Access> acc;
  for (const auto* it : items) acc.push_back(access_of(it));

  // Edges with the reason, for cycle reports.
  std::vector<std::vector<std::pair<std::size_t, std::string>>> out(n);
  auto index_of = [&](const std::string& name) -> std::ptrdiff_t {
    for (std::size_t i = 0; i < n; ++i)
      if (items[i]->name == name) return static_cast<std::ptrdiff_t>(i);
    return -1;
  };
  auto ordering = [&](std::size_t i, const OrderingRef& ref, bool before) {
    const std::ptrdiff_t j = index_of(ref.name);
    if (j < 0) {
      if (ref.optional) return;
      std::string where_else;
      for (const auto& [c, list] : by_container_)
        for (const auto* other : list)
          if (other->name == ref.name) where_else = c;
      if (!where_else.empty())
        throw InputError(ref.where, "'" + items[i]->name + "' is ordered relative to '" + ref.name + "', which is in '" +
                                        where_else + "', not in '" + container + "' (mark it optional or move it)");
      throw InputError(ref.where, "'" + items[i]->name + "' is ordered relative to '" + ref.name +
                                      "', which is not scheduled by any active thorn (add 'optional: true' if that is expected)");
    }
    const auto u = before ? i : static_cast<std::size_t>(j);
    const auto v = before ? static_cast<std::size_t>(j) : i;
    out[u].emplace_back(v, "'" + items[i]->name + "' declares " + (before ? "before: " : "after: ") + ref.name);
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& r : items[i]->before) ordering(i, r, true);
    for (const auto& r : items[i]->after) ordering(i, r, false);
  }
  // Writer before reader, unless both read and modify the group (then only explicit ordering).
  // Explicit before/after wins over what the accesses imply, also through chains: in a repeated
  // group (MoL's substeps) "PostStep writes prim, CalcRHS reads it" is carried to the next pass, and
  // CalcRHS -> Update -> PostStep is the declared order.
  std::vector<std::vector<bool>> explicit_reach(n, std::vector<bool>(n, false));
  for (std::size_t u = 0; u < n; ++u) {
    std::vector<std::size_t> stack{u};
    while (!stack.empty()) {
      const std::size_t w = stack.back();
      stack.pop_back();
      for (const auto& [v, why] : out[w])
        if (!explicit_reach[u][v]) {
          explicit_reach[u][v] = true;
          stack.push_back(v);
        }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || explicit_reach[i][j] || explicit_reach[j][i]) continue;
      for (int g : acc[i].writes) {
        if (!acc[j].reads.count(g)) continue;
        const bool both_modify = acc[i].reads.count(g) && acc[j].writes.count(g);
        if (both_modify) continue;
        out[i].emplace_back(j, "'" + items[i]->name + "' writes " + vars.group(g).full_name() + ", which '" +
                                   items[j]->name + "' reads");
        break;
      }
    }
  // Kahn's algorithm; ties broken by declaration order so the schedule is deterministic.
  std::vector<int> indeg(n, 0);
  for (std::size_t u = 0; u < n; ++u)
    for (const auto& [v, why] : out[u]) ++indeg[v];
  std::priority_queue<std::size_t, std::vector<std::size_t>, std::greater<>> ready;
  for (std::size_t u = 0; u < n; ++u)
    if (indeg[u] == 0) ready.push(u);
  std::vector<std::size_t> order;
  while (!ready.empty()) {
    const std::size_t u = ready.top();
    ready.pop();
    order.push_back(u);
    for (const auto& [v, why] : out[u])
      if (--indeg[v] == 0) ready.push(v);
  }
  if (order.size() != n) {
    // Every remaining item has a remaining predecessor: walk predecessors until one repeats.
    std::vector<bool> left(n, false);
    for (std::size_t u = 0; u < n; ++u) left[u] = indeg[u] > 0;
    std::vector<std::vector<std::pair<std::size_t, std::string>>> in(n);
    for (std::size_t u = 0; u < n; ++u)
      for (const auto& [v, why] : out[u])
        if (left[u] && left[v]) in[v].emplace_back(u, why);
    std::size_t start = 0;
    while (!left[start]) ++start;
    std::vector<std::size_t> path{start};
    std::map<std::size_t, std::size_t> pos{{start, 0}};
    std::vector<std::string> reasons;  // reasons[k]: edge path[k+1] -> path[k]
    for (std::size_t u = start;;) {
      const auto& [p, why] = in[u].front();
      reasons.push_back(why);
      if (pos.count(p)) {
        // The cycle, in execution order: p -> ... -> p.
        std::vector<std::size_t> cyc(path.begin() + static_cast<std::ptrdiff_t>(pos[p]), path.end());
        std::vector<std::string> why_cyc(reasons.begin() + static_cast<std::ptrdiff_t>(pos[p]), reasons.end());
        std::reverse(cyc.begin(), cyc.end());
        std::reverse(why_cyc.begin(), why_cyc.end());
        std::string msg = "schedule cycle in '" + container + "': " + item_label(*items[p]);
        for (std::size_t k = 0; k < cyc.size(); ++k) msg += " -> " + item_label(*items[cyc[k]]);
        msg += "\n  because:";
        for (const auto& w : why_cyc) msg += "\n    " + w;
        throw InputError(items[p]->where, msg);
      }
      pos[p] = path.size();
      path.push_back(p);
      u = p;
    }
  }

  std::vector<ScheduleNode> nodes;
  for (std::size_t u : order) {
    const ScheduleItem* it = items[u];
    ScheduleNode node;
    node.item = it;
    const std::string key = it->thorn + "::" + it->name;
    if (it->is_group) {
      if (depth > 16) throw InputError(it->where, "groups nested too deeply");
      node.children = build_container(it->name, by_container_[it->name], impl, vars, params, depth + 1);
      if (!it->repeat_while.empty()) {
        auto p = impl.predicates.find(it->thorn + "::" + it->repeat_while);
        if (p == impl.predicates.end())
          throw InputError(it->where, "group '" + it->name + "' repeats while '" + it->repeat_while + "', but thorn " +
                                          it->thorn + " registers no predicate of that name");
        node.repeat = p->second;
      }
    } else {
      auto f = impl.functions.find(key);
      if (f == impl.functions.end())
        throw InputError(it->where, "function " + key + " is declared but thorn " + it->thorn + " registers no implementation");
      node.fn = f->second;
      for (const auto& r : it->reads)
        for (int id : resolve_access(r, *it, vars, params, off_groups_.count(it->in) > 0)) {
          node.reads.push_back(id);
          if (r.region == Region::everywhere) node.reads_everywhere.push_back(id);
        }
      for (const auto& w : it->writes)
        for (int id : resolve_access(w, *it, vars, params, off_groups_.count(it->in) > 0))
          (w.region == Region::everywhere ? node.writes_everywhere : node.writes_interior).push_back(id);
      node.declared = node.reads;
      node.declared.insert(node.declared.end(), node.writes_interior.begin(), node.writes_interior.end());
      node.declared.insert(node.declared.end(), node.writes_everywhere.begin(), node.writes_everywhere.end());
      std::sort(node.declared.begin(), node.declared.end());
      node.declared.erase(std::unique(node.declared.begin(), node.declared.end()), node.declared.end());
    }
    if (!it->every_param.empty()) {
      const ParamSpec* spec = params.find(it->every_thorn, it->every_param);
      if (!spec || spec->type != ParamType::integer || spec->is_array)
        throw InputError(it->where, "'every: " + it->every_thorn + "::" + it->every_param +
                                        "' must name an int parameter of an active thorn");
      node.every_value = &params.get<std::int64_t>(it->every_thorn, it->every_param);
    }
    if (!it->condition.empty()) {
      const ParamSpec* spec = params.find(it->condition.thorn, it->condition.param);
      if (!spec)
        throw InputError(it->where, "condition '" + it->condition.text + "' names an unknown parameter (is thorn " +
                                        it->condition.thorn + " active?)");
      node.condition_value = &params.value(it->condition.thorn, it->condition.param);
      using Op = Condition::Op;
      if (it->condition.op == Op::equal || it->condition.op == Op::not_equal) {
        node.condition_expected = parse_param_value(*spec, YAML::Node(it->condition.value), it->where);
      } else if (spec->type != ParamType::boolean || spec->is_array) {
        throw InputError(it->where, "condition '" + it->condition.text + "' needs a bool parameter; use == or != for " +
                                        spec->type_name());
      }
    }
    nodes.push_back(std::move(node));
  }
  return nodes;
}

bool Scheduler::bin_empty(const std::string& bin) const {
  auto it = bins_.find(bin);
  return it == bins_.end() || it->second.empty();
}

void Scheduler::invalidate_ghosts() { std::fill(ghosts_valid_.begin(), ghosts_valid_.end(), false); }

bool Scheduler::condition_holds(const ScheduleNode& node, const Context& ctx) const {
  const ScheduleItem& it = *node.item;
  if (node.every_value) {
    if (*node.every_value <= 0 || ctx.iteration() % *node.every_value != 0) return false;
  } else if (it.every > 1 && ctx.iteration() % it.every != 0) {
    return false;
  }
  if (!node.condition_value) return true;
  switch (it.condition.op) {
    case Condition::Op::is_true: return std::get<bool>(*node.condition_value);
    case Condition::Op::is_false: return !std::get<bool>(*node.condition_value);
    case Condition::Op::equal: return *node.condition_value == node.condition_expected;
    case Condition::Op::not_equal: return *node.condition_value != node.condition_expected;
  }
  return true;
}

void Scheduler::run_bin(const std::string& bin, Context& ctx) {
  for (auto& node : bins_.at(bin)) run_node(node, ctx);
}

void Scheduler::run_node(ScheduleNode& node, Context& ctx) {
  if (!condition_holds(node, ctx)) return;
  const auto t0 = Clock::now();
  const double w0 = comm::work_seconds();
  if (node.item->is_group) {
    if (node.repeat) {
      ctx.set_current(node.item->thorn, node.item->repeat_while);
      while (node.repeat(ctx))
        for (auto& c : node.children) run_node(c, ctx);
    } else {
      for (auto& c : node.children) run_node(c, ctx);
    }
  } else {
    call_function(node, ctx);
  }
  node.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
  node.work_seconds += comm::work_seconds() - w0;
  ++node.calls;
}

namespace {

std::uint64_t checksum(Block& b, int group) {
  // FNV-1a over the raw bits: any change, NaN payloads included, changes the sum.
  std::uint64_t h = 1469598103934665603ull;
  const double* p = b.data(group);
  for (std::size_t i = 0; i < b.size(group); ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, &p[i], sizeof bits);
    h = (h ^ bits) * 1099511628211ull;
  }
  return h;
}

std::size_t count_nan_interior(Block& b, int group, const VariableGroupSpec& g) {
  std::size_t count = 0;
  const auto st = staggering(g.centering);
  for (int c = 0; c < g.ncomp(); ++c) {
    Field f = b.field(group, c);
    for (int k = 0; k < b.n[2] + (b.ng[2] > 0 || b.n[2] > 1 ? st[2] : 0); ++k)
      for (int j = 0; j < b.n[1] + (b.ng[1] > 0 || b.n[1] > 1 ? st[1] : 0); ++j)
        for (int i = 0; i < b.n[0] + st[0]; ++i)
          if (std::isnan(f(i, j, k))) ++count;
  }
  return count;
}

// "component v1 at cell (3, 0, 0), x = (0.27, 1.57, 3.14)" for the first NaN of the interior.
std::string first_nan(Block& b, int group, const VariableGroupSpec& g) {
  const auto st = staggering(g.centering);
  for (int c = 0; c < g.ncomp(); ++c) {
    Field f = b.field(group, c);
    for (int k = 0; k < b.n[2] + (b.ng[2] > 0 || b.n[2] > 1 ? st[2] : 0); ++k)
      for (int j = 0; j < b.n[1] + (b.ng[1] > 0 || b.n[1] > 1 ? st[1] : 0); ++j)
        for (int i = 0; i < b.n[0] + st[0]; ++i)
          if (std::isnan(f(i, j, k))) {
            std::ostringstream os;
            os << "first: component " << g.components[static_cast<std::size_t>(c)].name << " at cell (" << i << ", " << j
               << ", " << k << "), x = (" << b.centroid(0, i) << ", " << b.centroid(1, j) << ", " << b.centroid(2, k)
               << ")";
            return os.str();
          }
  }
  return "none";
}

}  // namespace

void Scheduler::call_function(ScheduleNode& node, Context& ctx) {
  const ScheduleItem& it = *node.item;
  ctx.set_current(it.thorn, it.name);
  // Ghost zones the function will read must be current: synchronise the stale ones first.
  std::vector<int> stale;
  for (int g : node.reads_everywhere)
    if (!ghosts_valid_[static_cast<std::size_t>(g)]) stale.push_back(g);
  if (!stale.empty()) {
    if (!ctx.has_grid())
      throw RunError(it.thorn + "::" + it.name + " reads variables everywhere, but no active thorn provides a grid");
    const auto t0 = Clock::now();
    ctx.grid().synchronize(stale);
    sync_seconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
    ++sync_calls_;
    for (int g : stale) ghosts_valid_[static_cast<std::size_t>(g)] = true;
    ctx.set_current(it.thorn, it.name);
  }

  std::vector<std::pair<int, std::vector<std::uint64_t>>> sums;
  std::set<int> declared_writes(node.writes_interior.begin(), node.writes_interior.end());
  declared_writes.insert(node.writes_everywhere.begin(), node.writes_everywhere.end());
  if (debug_ && ctx.has_grid()) {
    const std::set<int> reads(node.reads.begin(), node.reads.end());
    auto blocks = ctx.grid().local_blocks();
    for (int g : declared_writes)
      if (!reads.count(g))
        for (Block* b : blocks) std::fill(b->data(g), b->data(g) + b->size(g), std::numeric_limits<double>::quiet_NaN());
    for (int g = 0; g < vars_->size(); ++g) {
      if (declared_writes.count(g)) continue;
      std::vector<std::uint64_t> s;
      for (Block* b : blocks) s.push_back(checksum(*b, g));
      sums.emplace_back(g, std::move(s));
    }
  }

  if (debug_) {
    // Views of undeclared groups throw while the function runs; nested bins restore the outer set.
    const std::vector<int>* outer = ctx.set_declared_groups(&node.declared);
    try {
      node.fn(ctx);
    } catch (...) {
      ctx.set_declared_groups(outer);
      throw;
    }
    ctx.set_declared_groups(outer);
  } else {
    node.fn(ctx);
  }

  if (debug_ && ctx.has_grid()) {
    auto blocks = ctx.grid().local_blocks();
    for (const auto& [g, s] : sums)
      for (std::size_t b = 0; b < blocks.size(); ++b)
        if (checksum(*blocks[b], g) != s[b])
          throw RunError("debug check: " + it.thorn + "::" + it.name + " changed " + vars_->group(g).full_name() +
                         " without declaring it in 'writes' (" + it.where.str() + ")");
    for (int g : declared_writes)
      for (Block* b : blocks)
        if (std::size_t bad = count_nan_interior(*b, g, vars_->group(g)))
          throw RunError("debug check: after " + it.thorn + "::" + it.name + ", " + std::to_string(bad) +
                         " interior points of " + vars_->group(g).full_name() + " on block " + std::to_string(b->gid) +
                         " are NaN: the function declares it writes them but did not (" + it.where.str() + ")");
  }
  if (nan_check_ && !debug_ && ctx.has_grid())
    for (int g : declared_writes)
      for (Block* b : ctx.grid().local_blocks())
        if (std::size_t bad = count_nan_interior(*b, g, vars_->group(g)))
          throw RunError(it.thorn + "::" + it.name + " wrote NaN into " + std::to_string(bad) + " interior points of " +
                         vars_->group(g).full_name() + " on block " + std::to_string(b->gid) + " (" +
                         first_nan(*b, g, vars_->group(g)) + "); initial data must be finite: check its parameters");
  for (int g : node.writes_interior) ghosts_valid_[static_cast<std::size_t>(g)] = false;
  for (int g : node.writes_everywhere) ghosts_valid_[static_cast<std::size_t>(g)] = true;
}

std::string Scheduler::print() const {
  std::ostringstream os;
  std::function<void(const ScheduleNode&, int)> emit = [&](const ScheduleNode& node, int indent) {
    const ScheduleItem& it = *node.item;
    std::string label = std::string(static_cast<std::size_t>(indent), ' ') + it.thorn + "::" + it.name;
    if (it.is_group) label += " (group)";
    os << std::left << std::setw(44) << label << " " << it.description;
    std::vector<std::string> notes;
    if (!it.repeat_while.empty()) notes.push_back("repeat while " + it.repeat_while);
    if (it.every > 1) notes.push_back("every " + std::to_string(it.every) + " iterations");
    if (!it.every_param.empty()) notes.push_back("every " + it.every_thorn + "::" + it.every_param + " iterations");
    if (!it.condition.empty()) notes.push_back("if " + it.condition.text);
    if (!node.reads_everywhere.empty()) {
      std::vector<std::string> names;
      for (int g : node.reads_everywhere) names.push_back(vars_->group(g).full_name());
      notes.push_back("syncs " + join(names));
    }
    if (!notes.empty()) os << "  [" << join(notes, "; ") << "]";
    os << "\n";
    for (const auto& c : node.children) emit(c, indent + 2);
  };
  for (const auto& bin : standard_bins()) {
    const auto& nodes = bins_.at(bin);
    os << bin << ":" << (nodes.empty() ? " (empty)" : "") << "\n";
    for (const auto& n : nodes) emit(n, 2);
  }
  return os.str();
}

std::vector<const ScheduleNode*> Scheduler::all_functions() const {
  std::vector<const ScheduleNode*> out;
  std::function<void(const ScheduleNode&)> walk = [&](const ScheduleNode& n) {
    out.push_back(&n);
    for (const auto& c : n.children) walk(c);
  };
  for (const auto& bin : standard_bins())
    for (const auto& n : bins_.at(bin)) walk(n);
  return out;
}

std::string Scheduler::timer_table() const {
  std::ostringstream os;
  double total = 0;
  for (const auto& bin : standard_bins())
    for (const auto& n : bins_.at(bin)) total += n.seconds;
  os << "Timers (rank 0):\n";
  os << "  " << std::left << std::setw(46) << "scheduled item" << std::right << std::setw(10) << "calls" << std::setw(12)
     << "seconds" << std::setw(8) << "%" << "\n";
  std::function<void(const ScheduleNode&, int)> emit = [&](const ScheduleNode& n, int indent) {
    if (n.calls == 0) return;
    std::string label = std::string(static_cast<std::size_t>(indent), ' ') + n.item->thorn + "::" + n.item->name;
    os << "  " << std::left << std::setw(46) << label << std::right << std::setw(10) << n.calls << std::setw(12)
       << std::fixed << std::setprecision(4) << n.seconds << std::setw(8) << std::setprecision(1)
       << (total > 0 ? 100.0 * n.seconds / total : 0.0) << "\n";
    for (const auto& c : n.children) emit(c, indent + 2);
  };
  for (const auto& bin : standard_bins()) {
    double s = 0;
    for (const auto& n : bins_.at(bin)) s += n.seconds;
    if (bins_.at(bin).empty()) continue;
    os << "  [" << bin << "] " << std::fixed << std::setprecision(4) << s << " s\n";
    for (const auto& n : bins_.at(bin)) emit(n, 2);
  }
  os << "  automatic ghost synchronisation (included above): " << sync_calls_ << " calls, " << std::fixed
     << std::setprecision(4) << sync_seconds_ << " s\n";
  return os.str();
}

}  // namespace remnant
