#pragma once
// Length units for fabrication output. The mesh carries no unit, so it is taken to be in
// metres unless the designer says otherwise (--mesh-units); the parts list and cut sheets
// are written in the designer's units (--units, default: the mesh's units, so a plain run
// keeps the numbers of the mesh file).
#include <string>

namespace ff {

enum class LengthUnit { Millimetre, Centimetre, Metre, Inch, Foot };

// "mm", "cm", "m", "in", "ft"; throws InputError naming `what` for anything else.
LengthUnit parse_length_unit(const std::string& text, const std::string& what);
const char* unit_name(LengthUnit unit);
double metres_per_unit(LengthUnit unit);
// Multiply a length in `from` by this to get it in `to`.
double unit_scale(LengthUnit from, LengthUnit to);

}  // namespace ff
