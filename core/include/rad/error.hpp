#pragma once

#include <stdexcept>
#include <string>

namespace rad {

// Bad input from the user: a file, a line of it, or an option. The program reports the message on one line
// and exits with status 2; anything else that goes wrong exits with status 1.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace rad
