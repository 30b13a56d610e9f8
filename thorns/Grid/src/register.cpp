// Binds the Grid thorn to the flesh: it provides the mesh.
#include <memory>

#include "Grid/uniform_grid.hpp"
#include "remnant/registrar.hpp"

REMNANT_REGISTER_THORN(Grid) {
  reg.grid_factory([](const remnant::GridSetup& setup) -> std::unique_ptr<remnant::GridDriver> {
    return std::make_unique<remnant::grid::UniformGrid>(setup);
  });
}
