// Writing a strand species back to its file format (docs/species.md), as `ecoforest design`
// saves it. Every number is written in its shortest form that reads back to the same
// double, so a saved species loads to the same parameters and builds the same tree, byte
// for byte. The [ecology] tables, which the model does not read, are copied from the
// species' own file as they stand there, comments and all, so a designed species still
// grows in `ecoforest run`.
#pragma once

#include <filesystem>
#include <string>

#include "model/species.hpp"

namespace eco {

// The species file's text. `ecology` is appended as it is (see ecologyTablesOf).
std::string speciesToml(const Species& species, const std::string& ecology);

// The text of a species file's [ecology] tables and their sub-tables, each with the comment
// lines just above its header; empty when the file has none or cannot be read.
std::string ecologyTablesOf(const std::filesystem::path& speciesFile);

// Writes the species (and the ecology of species.file) to `file` atomically. InputError for
// an L-system species: its tree is a grammar, which the designer does not edit.
void saveSpecies(const Species& species, const std::filesystem::path& file);

}  // namespace eco
