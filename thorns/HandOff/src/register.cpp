// HandOff's scheduled functions (thorn.yaml).
#include "import.hpp"
#include "remnant/registrar.hpp"

REMNANT_REGISTER_THORN(HandOff) {
  reg.function("HandOff_CheckParameters", remnant::handoff::check_parameters);
  reg.function("HandOff_Initial", remnant::handoff::initial);
  reg.function("HandOff_ImportConserved", remnant::handoff::import_conserved);
  reg.function("HandOff_Report", remnant::handoff::report);
}
