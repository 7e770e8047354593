# OpenGL and EGL functions are loaded by a glad 2 loader generated at build time (Debian: python3-glad) from
# the Khronos registry files packaged with it. Unlike libepoxy, which resolves functions only while a GLX or
# EGL context is current, glad takes any get-proc-address function, so the same renderer runs on EGL, on
# OSMesa (the headless fallback) and in a GLFW window. Only OpenGL 3.3 core and the EGL extensions the
# headless context uses are generated.
find_program(GLAD_EXECUTABLE glad REQUIRED)

set(RAD_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
set(RAD_GLAD_EGL_EXTENSIONS
    EGL_EXT_platform_base,EGL_EXT_device_base,EGL_EXT_device_enumeration,EGL_EXT_device_query,EGL_EXT_platform_device,EGL_MESA_platform_surfaceless,EGL_KHR_no_config_context)
set(RAD_GLAD_OUTPUTS ${RAD_GLAD_DIR}/src/gl.c ${RAD_GLAD_DIR}/src/egl.c ${RAD_GLAD_DIR}/include/glad/gl.h
                     ${RAD_GLAD_DIR}/include/glad/egl.h)
add_custom_command(
  OUTPUT ${RAD_GLAD_OUTPUTS}
  COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=3.3,egl=1.5
          --extensions ${RAD_GLAD_EGL_EXTENSIONS} --out-path ${RAD_GLAD_DIR} c --loader
  DEPENDS ${CMAKE_CURRENT_LIST_FILE}
  COMMENT "Generating the OpenGL 3.3 and EGL 1.5 loader (glad)"
  VERBATIM)

add_library(radglad STATIC ${RAD_GLAD_DIR}/src/gl.c ${RAD_GLAD_DIR}/src/egl.c)
# SYSTEM: the generated headers are not ours to warn about.
target_include_directories(radglad SYSTEM PUBLIC ${RAD_GLAD_DIR}/include)
target_link_libraries(radglad PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(radglad PROPERTIES POSITION_INDEPENDENT_CODE ON)
