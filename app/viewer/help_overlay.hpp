#pragma once

#include <string_view>
#include <vector>

namespace rad {

// One line of the viewer's help: the keys (or mouse action) and what they do.
struct KeyHelp {
    std::string_view keys;
    std::string_view action;
};

// Every key and mouse action the window takes, in the order the help lists them.
const std::vector<KeyHelp>& viewer_key_help();

// The F1 overlay: the keys, in a Dear ImGui window centred at (x, y) in window units; clears `open` when
// its close button is pressed.
void draw_help_overlay(bool& open, float x, float y);

}  // namespace rad
