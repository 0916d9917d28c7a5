#include "model/lsystem/lsystem.hpp"

#include <charconv>

namespace eco {

std::string symbolName(Symbol symbol) {
  switch (symbol) {
    case kQueryPosition:
      return "?P";
    case kQueryHeading:
      return "?H";
    case kQueryUp:
      return "?U";
    case kQueryLeft:
      return "?L";
    case kSwitch:
      return "@Switch";
    case kPendulum:
      return "@Pendulum";
    case kRepetition:
      return "@Repetition";
    default:
      return std::string(1, static_cast<char>(symbol));
  }
}

bool isQuery(Symbol symbol) {
  return symbol >= kQueryPosition && symbol <= kQueryLeft;
}

bool isControl(Symbol symbol) {
  return symbol == kSwitch || symbol == kPendulum || symbol == kRepetition;
}

void ModuleString::add(Symbol symbol, std::initializer_list<double> values) {
  add(symbol, values.begin(), static_cast<int>(values.size()));
}

void ModuleString::add(Symbol symbol, const double* values, int count) {
  modules.push_back({symbol, static_cast<std::uint16_t>(count),
                     static_cast<std::uint32_t>(params.size()), kNoBody});
  params.insert(params.end(), values, values + count);
}

void ModuleString::append(const ModuleString& from, std::size_t i) {
  const Module& m = from.modules[i];
  add(m.symbol, from.paramsOf(m), m.paramCount);
  if (m.body != kNoBody) {
    modules.back().body = static_cast<std::uint32_t>(bodies.size());
    bodies.push_back(from.bodies[m.body]);
  }
}

void ModuleString::clear() {
  modules.clear();
  params.clear();
  bodies.clear();
}

void instantiate(const StringTemplate& t, const EvalEnv& env, ModuleString& out) {
  if (t.constant) {
    const auto base = static_cast<std::uint32_t>(out.params.size());
    const std::size_t first = out.modules.size();
    out.modules.insert(out.modules.end(), t.prebuilt.modules.begin(), t.prebuilt.modules.end());
    if (!t.prebuilt.params.empty()) {
      out.params.insert(out.params.end(), t.prebuilt.params.begin(), t.prebuilt.params.end());
      for (std::size_t k = first; k < out.modules.size(); ++k) out.modules[k].firstParam += base;
    }
    return;
  }
  double values[256];
  for (const ModuleTemplate& m : t.modules) {
    const int count = static_cast<int>(m.params.size());
    for (int k = 0; k < count; ++k) values[k] = evaluate(m.params[k], env);
    out.add(m.symbol, values, count);
    if (m.body >= 0) {
      ModuleString body;
      instantiate(t.bodies[static_cast<std::size_t>(m.body)], env, body);
      out.modules.back().body = static_cast<std::uint32_t>(out.bodies.size());
      out.bodies.push_back(std::move(body));
    }
  }
}

std::size_t branchEnd(const ModuleString& string, std::size_t from) {
  int depth = 0;
  for (std::size_t i = from; i < string.size(); ++i) {
    const Symbol s = string.modules[i].symbol;
    if (s == ']' && depth == 0) return i;
    depth += s == '[' ? 1 : s == ']' ? -1 : 0;
  }
  return string.size();
}

namespace {

void appendNumber(std::string& out, double value) {
  char buffer[32];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, end);
}

void appendString(std::string& out, const ModuleString& string) {
  for (const Module& m : string.modules) {
    out += symbolName(m.symbol);
    if (m.paramCount > 0) {
      out += '(';
      for (int k = 0; k < m.paramCount; ++k) {
        if (k > 0) out += ',';
        appendNumber(out, string.params[m.firstParam + static_cast<std::size_t>(k)]);
      }
      out += ')';
    }
    if (m.body != kNoBody) {
      out += '{';
      appendString(out, string.bodies[m.body]);
      out += '}';
    }
  }
}

}  // namespace

std::string toString(const ModuleString& string) {
  std::string out;
  out.reserve(string.size() * 2);
  appendString(out, string);
  return out;
}

bool PruneVolume::contains(const glm::dvec3& p) const {
  switch (shape) {
    case PruneShape::None:
      return true;
    case PruneShape::Ellipsoid: {
      const glm::dvec3 d = (p - center) / extent;
      return d.x * d.x + d.y * d.y + d.z * d.z <= 1.0 + 1e-9;
    }
    case PruneShape::Box:
      return p.x >= center.x - 1e-9 && p.y >= center.y - 1e-9 && p.z >= center.z - 1e-9 &&
             p.x <= extent.x + 1e-9 && p.y <= extent.y + 1e-9 && p.z <= extent.z + 1e-9;
  }
  return true;
}

}  // namespace eco
