#pragma once
// The fabrication options of `flatfacet remesh` (--thickness, --side, --units, --mesh-units,
// --parts, --sheets, --sheet-size, --solid) and the files they produce.
#include <set>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/output.h"
#include "core/fabricate/cut_sheets.h"
#include "core/fabricate/parts_list.h"

namespace ff::cli {

struct FabricationRequest {
  FabricationOptions options;
  std::string parts, sheets, solid;  // output paths, empty when not asked for
  SheetOptions sheet;
  bool any() const { return !parts.empty() || !sheets.empty() || !solid.empty(); }
};

// The option names this adds to `remesh`.
const std::set<std::string>& fabrication_option_names();

// Parses and checks them (UsageError naming the option).
FabricationRequest parse_fabrication(const Args& args);

// The files asked for, from the final panels. `folded` (when given) gets the labels of the
// parts whose inner face folds over (PartsList::folded_inner_faces).
std::vector<OutputFile> fabrication_outputs(const FabricationRequest& request, const PanelMesh& panels,
                                            std::vector<std::string>* folded = nullptr);

}  // namespace ff::cli
