// Reads an RL-system grammar in the Green tool's layout (Lluch et al., section 2):
//   SYSTEM name / DECLARATIONS ... / AXIOM ... / RULES ... / END.
// Every syntax error is an InputError at file:line:column. docs/lsystems.md is the reference.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "model/lsystem/lsystem.hpp"

namespace eco {

LSystem loadLSystem(const std::filesystem::path& file);
// `fileName` only names the text in messages.
LSystem parseLSystem(std::string_view text, const std::string& fileName);

}  // namespace eco
