#include "material.h"

namespace rtvk {

std::string type_name(material_type t) {
  switch (t) {
    case material_type::normal:
      return "normal";
    case material_type::lambertian:
      return "lambertian";
    case material_type::metal:
      return "metal";
    case material_type::dielectric:
      return "dielectric";
  }
  return "unknown";
}

}  // namespace rtvk
