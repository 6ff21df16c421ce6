# Embeds every GLSL file of shaders/ into a generated C++ source, so the binary runs
# from any directory. The generated file defines cloudsvc::shader_source(name).
set(CLOUDSVC_SHADER_DIR ${CMAKE_SOURCE_DIR}/shaders)
file(GLOB CLOUDSVC_SHADER_FILES CONFIGURE_DEPENDS ${CLOUDSVC_SHADER_DIR}/*.glsl
     ${CLOUDSVC_SHADER_DIR}/*.comp ${CLOUDSVC_SHADER_DIR}/*.frag ${CLOUDSVC_SHADER_DIR}/*.vert)
set(CLOUDSVC_EMBEDDED_SHADERS_CPP ${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp)
add_custom_command(
  OUTPUT ${CLOUDSVC_EMBEDDED_SHADERS_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUT=${CLOUDSVC_EMBEDDED_SHADERS_CPP}
          "-DFILES=${CLOUDSVC_SHADER_FILES}" -P ${CMAKE_SOURCE_DIR}/cmake/embed_shaders_script.cmake
  DEPENDS ${CLOUDSVC_SHADER_FILES} ${CMAKE_SOURCE_DIR}/cmake/embed_shaders_script.cmake
  COMMENT "Embedding GLSL shaders"
  VERBATIM)
