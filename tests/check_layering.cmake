# Folder layering of the GL-free code (run by ctest as Layering.GlFreeFoldersIncludeNoGlHeaders):
# the physical model (renderer/model), the CPU reference (renderer/reference), the ground
# truth (renderer/truth), the renderer's
# plain-data API (renderer/api), weather/, geodesy/ and protocol/ include no header of the
# GL renderer (renderer/*.h at its top level, renderer/gl/), of the service, and no GL,
# EGL or GLFW header. Usage: cmake -DSOURCE_DIR=<repo> -P check_layering.cmake
set(gl_free_dirs renderer/model renderer/reference renderer/truth renderer/api weather geodesy protocol)
set(violations "")
foreach(dir ${gl_free_dirs})
  file(GLOB_RECURSE files ${SOURCE_DIR}/${dir}/*.h ${SOURCE_DIR}/${dir}/*.cpp)
  foreach(f ${files})
    file(STRINGS ${f} includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${includes})
      if(line MATCHES "\"renderer/[a-z_0-9]+\\.h\"" OR line MATCHES "\"renderer/gl/" OR line MATCHES "\"service/"
         OR line MATCHES "<epoxy/" OR line MATCHES "<EGL/" OR line MATCHES "<GL/" OR line MATCHES "<GLFW/")
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        string(APPEND violations "  ${rel}: ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "GL-free folders include GL-side headers:\n${violations}")
endif()
message(STATUS "layering ok: ${gl_free_dirs}")
