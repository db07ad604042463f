#include "model/point/validity.hpp"

namespace punchsweep::model {

std::string_view validity_name(Validity v) {
  switch (v) {
    case Validity::valid: return "valid";
    case Validity::same_level_overlap: return "same_level_overlap";
    case Validity::cross_level_overlap: return "cross_level_overlap";
    case Validity::no_solution: return "no_solution";
    case Validity::inaccurate: return "inaccurate";
    case Validity::outside_table: return "outside_table";
    case Validity::unloading: return "unloading";
  }
  return "unknown";
}

}  // namespace punchsweep::model
