#pragma once

#include <string>
#include <vector>

namespace rad {

// The comma-separated numbers of an option's value ("1,2,3"), each a whole finite number. Throws
// InputError "WHERE: 'ITEM' is not a number (want WANT)" at the first that is not.
std::vector<double> comma_numbers(const std::string& text, const std::string& where, const std::string& want);

}  // namespace rad
