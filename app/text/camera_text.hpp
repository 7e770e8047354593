#pragma once

#include <string>
#include <vector>

#include "rad/scene/scene.hpp"

namespace rad {

// A camera as `render --camera` takes it: "ex,ey,ez,tx,ty,tz[,ux,uy,uz]" (eye, target, up), the field of view
// from `fallback` (and its up when not given). `where` names the text in errors: "--camera", or "FILE:LINE".
// Throws InputError for anything else, or a camera that looks nowhere.
Camera parse_camera(const std::string& text, const Camera& fallback, const std::string& where);

// The options that give `render` this camera: "--camera ex,ey,ez,tx,ty,tz,ux,uy,uz --fov F", each number
// with the digits that read it back to within a millionth of the scene's size (the viewer's copy).
std::string camera_option_text(const Camera& camera);

// A cameras file `render --cameras` reads: one "ex,ey,ez,tx,ty,tz,ux,uy,uz" line per camera, after a comment
// line naming the field of view (the file holds none: --fov sets it).
std::string cameras_file_text(const std::vector<Camera>& cameras);

}  // namespace rad
