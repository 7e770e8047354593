#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "rad/util/error.hpp"

namespace rad::test {

// Expects load(path) to throw InputError with a one-line message that contains every one of `parts`.
template <typename Load>
void expect_input_error(Load load, const std::string& path, std::initializer_list<std::string> parts) {
    try {
        load(path);
        ADD_FAILURE() << path << ": expected an InputError";
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const std::string& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
    }
}

}  // namespace rad::test
