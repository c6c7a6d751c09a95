#include "core/fabricate/units.h"

#include "core/util/error.h"

namespace ff {

LengthUnit parse_length_unit(const std::string& text, const std::string& what) {
  if (text == "mm") return LengthUnit::Millimetre;
  if (text == "cm") return LengthUnit::Centimetre;
  if (text == "m") return LengthUnit::Metre;
  if (text == "in") return LengthUnit::Inch;
  if (text == "ft") return LengthUnit::Foot;
  throw InputError(what + ": expected mm, cm, m, in or ft, got '" + text + "'");
}

const char* unit_name(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return "mm";
    case LengthUnit::Centimetre:
      return "cm";
    case LengthUnit::Metre:
      return "m";
    case LengthUnit::Inch:
      return "in";
    case LengthUnit::Foot:
      return "ft";
  }
  return "m";
}

double metres_per_unit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Millimetre:
      return 0.001;
    case LengthUnit::Centimetre:
      return 0.01;
    case LengthUnit::Metre:
      return 1.0;
    case LengthUnit::Inch:
      return 0.0254;  // exact by definition
    case LengthUnit::Foot:
      return 0.3048;
  }
  return 1.0;
}

double unit_scale(LengthUnit from, LengthUnit to) { return metres_per_unit(from) / metres_per_unit(to); }

}  // namespace ff
