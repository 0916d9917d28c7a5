#include "model/species_writer.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "model/species_schema.hpp"

namespace eco {
namespace {

// The shortest text that reads back to the same double; integral values keep a ".0" so
// that the file shows a real number where the schema has one.
std::string number(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  ECO_ASSERT(error == std::errc{}, "value " << value);
  std::string out(text, end);
  if (out.find_first_of(".en") == std::string::npos) out += ".0";
  return out;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\')
      out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      out += escape;
    } else
      out += c;
  }
  return out + "\"";
}

std::string numbers(std::initializer_list<double> values) {
  std::string out = "[";
  for (double v : values) out += (out.size() > 1 ? ", " : "") + number(v);
  return out + "]";
}

std::string polyline(const Polyline& line) {
  std::string out = "[";
  for (const ControlPoint& p : line.points())
    out += (out.size() > 1 ? ", " : "") + numbers({p.x, p.y});
  return out + "]";
}

// "key = value" with the value's meaning as a comment in a column.
void line(std::ostringstream& out, std::string_view key, const std::string& value,
          std::string_view comment = {}) {
  std::string text = std::string(key) + " = " + value;
  if (!comment.empty()) {
    if (text.size() < 34) text.resize(34, ' ');
    text += " # " + std::string(comment);
  }
  out << text << "\n";
}

bool isHeader(const std::string& text, std::string& name) {
  const std::size_t start = text.find_first_not_of(" \t");
  if (start == std::string::npos || text[start] != '[') return false;
  const std::size_t open = text.find_first_not_of("[ \t", start);
  const std::size_t close = text.find(']', open);
  if (open == std::string::npos || close == std::string::npos) return false;
  name = text.substr(open, close - open);
  name.erase(name.find_last_not_of(" \t") + 1);
  return true;
}

bool isComment(const std::string& text) {
  const std::size_t start = text.find_first_not_of(" \t");
  return start != std::string::npos && text[start] == '#';
}

}  // namespace

std::string speciesToml(const Species& species, const std::string& ecology) {
  ECO_ASSERT(species.generator == TreeGenerator::Strand, species.name);
  std::ostringstream out;
  out << "# " << (species.latinName.empty() ? species.name : species.latinName)
      << ", saved by `ecoforest design`";
  if (!species.file.empty()) out << " from " << species.file.filename().string();
  out << ".\n";
  line(out, "name", quoted(species.name));
  if (!species.latinName.empty()) line(out, "latin_name", quoted(species.latinName));
  if (!species.commonNames.empty()) {
    std::string names = "[";
    for (const std::string& name : species.commonNames)
      names += (names.size() > 1 ? ", " : "") + quoted(name);
    line(out, "common_names", names + "]");
  }

  out << "\n[strand]\n";
  const StrandParams& p = species.strand;
  const WindParams& w = species.wind;
  for (const GlobalParameterInfo& info : globalParameters()) {
    const double value = valueOf(species, info.parameter);
    line(out, info.key,
         info.integer ? std::to_string(static_cast<long long>(value)) : number(value), info.symbol);
    if (info.parameter == GlobalParameter::LeafDensity)
      line(out, "leaf_distribution", quoted(toString(p.leafDistribution)), "l_type");
    if (info.parameter == GlobalParameter::WindUndirected)
      line(out, "wind_direction", numbers({w.direction.x, w.direction.y, w.direction.z}),
           "w, tree frame: x east, y up, z south");
  }
  line(out, "lod", std::to_string(p.lod), "l_LOD");

  out << "\n[strand.local]\n";
  for (const LocalGraphInfo& info : localGraphs())
    line(out, info.key, polyline(graphOf(p.graphs, info.graph)));

  const Variation& v = species.variation;
  out << "\n[variation]\n";
  line(out, "branch_angle", number(v.branchAngle));
  line(out, "phyllotaxis_deg", number(v.phyllotaxis_deg));
  line(out, "length", number(v.length));

  const Appearance& a = species.appearance;
  out << "\n[appearance]\n";
  line(out, "bark_color", numbers({a.barkColor.r, a.barkColor.g, a.barkColor.b}), "sRGB");
  line(out, "bark_roughness", number(a.barkRoughness));
  line(out, "leaf_color", numbers({a.leafColor.r, a.leafColor.g, a.leafColor.b}));
  line(out, "leaf_shape", quoted(toString(a.leafShape)));

  if (!ecology.empty()) out << "\n" << ecology;
  return out.str();
}

std::string ecologyTablesOf(const std::filesystem::path& speciesFile) {
  std::ifstream in(speciesFile);
  std::vector<std::string> lines;
  for (std::string text; std::getline(in, text);) lines.push_back(text);
  // Each line belongs to the table whose header is the last above it, except that the
  // comment lines just above a header introduce that header's table.
  std::vector<std::string> owner(lines.size());
  std::string current;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string name;
    if (isHeader(lines[i], name)) {
      current = name;
      for (std::size_t c = i; c > 0 && isComment(lines[c - 1]); --c) owner[c - 1] = name;
    }
    owner[i] = current;
  }
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (owner[i] == "ecology" || owner[i].starts_with("ecology.")) out += lines[i] + "\n";
  return out;
}

void saveSpecies(const Species& species, const std::filesystem::path& file) {
  if (species.generator != TreeGenerator::Strand)
    throw InputError(
        SourceLocation(species.file.string(), 0, "generator"),
        species.name + " grows from an RL-system grammar; only strand species can be saved");
  const std::string text =
      speciesToml(species, species.file.empty() ? std::string() : ecologyTablesOf(species.file));
  AtomicFile out(file);
  out.write(text);
  out.commit();
}

}  // namespace eco
