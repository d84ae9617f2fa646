#pragma once
// One declaration per parameter: name, type, unit, default, range and
// description. The same declaration drives XML parsing and validation,
// `soak params` and the generated reference page Doc/scene-format.md.
#include <limits>
#include <string>
#include <vector>

#include "Base/Vec3.h"

namespace soak {

enum class ParamType { Real, Integer, Boolean, Vector, Text, Choice, IntegerList };

// What a Text parameter holds, for validation: free text; a name that
// becomes part of a file name (Base/SafeName.h); a path of a file the run
// reads (resolved from the scene's folder; the output folder may not hold it).
enum class TextKind { Plain, Name, InputFile };

const char* paramTypeName(ParamType t);

struct ParamDecl {
  std::string name;
  ParamType type = ParamType::Real;
  std::string unit;           // SI unit, "" for dimensionless
  std::string defaultValue;   // as it would be written in XML; "" with required
  bool required = false;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;  // (min, max] instead of [min, max]
  std::vector<std::string> choices;  // for Choice
  TextKind textKind = TextKind::Plain;  // for Text
  std::string description;

  std::string rangeText() const;  // e.g. "(0, 1]" or "one of: a, b"
};

// A parsed value of any ParamType.
struct ParamValue {
  ParamType type = ParamType::Real;
  double real = 0.0;
  long long integer = 0;
  bool boolean = false;
  Vec3 vector;
  std::string text;
  std::vector<long long> list;
};

}  // namespace soak
