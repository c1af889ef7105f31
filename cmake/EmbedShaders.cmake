# Embeds the files under shaders/ into a generated C++ source so that the binary
# never reads shaders from disk at run time. Each file becomes an entry of
# tofsim::gl::embeddedShaders(), keyed by its file name (e.g. "direct_gather.comp").
#
# The generation runs at build time (add_custom_command), so editing a shader
# rebuilds the table without re-running CMake's configure step.

set(TOFSIM_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedShadersScript.cmake)

function(tofsim_embed_shaders out_var)
  set(shader_files ${ARGN})
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/EmbeddedShaders.cpp)
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${generated} "-DFILES=${shader_files}"
            -P ${TOFSIM_EMBED_SCRIPT}
    DEPENDS ${shader_files} ${TOFSIM_EMBED_SCRIPT}
    COMMENT "Embedding shaders"
    VERBATIM)
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction()
