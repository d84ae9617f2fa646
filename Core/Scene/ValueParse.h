#pragma once
#include <string>

#include "Registry/Param.h"

namespace soak {

// Parses `text` as the declared parameter. On failure returns false and sets
// `error` to what is wrong and what is allowed (no location).
bool parseParamValue(const ParamDecl& decl, const std::string& text, ParamValue& out, std::string& error);

}  // namespace soak
