#include "remnant/context.hpp"

#include <algorithm>
#include <iostream>

namespace remnant {

Context::Context(const Parameters& params, const VariableRegistry& vars, MPI_Comm comm)
    : params_(&params), vars_(&vars), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &nranks_);
}

int Context::var(const std::string& full_name) const {
  const int id = vars_->find(full_name);
  if (id < 0) throw RunError("no variable group named '" + full_name + "' (is its thorn active?)");
  return id;
}

void Context::check_declared(int group) const {
  if (std::binary_search(declared_groups_->begin(), declared_groups_->end(), group)) return;
  throw RunError("debug check: " + current_thorn_ + "::" + current_function_ + " accesses " +
                 vars_->group(group).full_name() +
                 ", which its schedule entry does not declare in 'reads' or 'writes' (thorn.yaml)");
}

GridDriver& Context::grid() const {
  if (!grid_) throw RunError("no grid: activate a thorn that provides 'grid' (e.g. Grid)");
  return *grid_;
}

void Context::info(const std::string& msg) const {
  if (rank_ == 0) std::cout << "INFO " << current_thorn_ << "::" << current_function_ << ": " << msg << std::endl;
}

void Context::warn(const std::string& msg) const {
  std::cerr << "WARNING [rank " << rank_ << "] " << current_thorn_ << "::" << current_function_ << ": " << msg
            << std::endl;
}

}  // namespace remnant
