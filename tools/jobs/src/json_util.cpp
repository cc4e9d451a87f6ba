#include "json_util.h"

#include <sstream>

namespace cordgrasp {

std::string vec_text(const nlohmann::json& j) {
  std::ostringstream s;
  s.precision(4);
  s << '(' << j.at(0).get<double>() << ", " << j.at(1).get<double>() << ", "
    << j.at(2).get<double>() << ')';
  return s.str();
}

}  // namespace cordgrasp
