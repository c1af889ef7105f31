# Embeds files into a generated C++ source so that the binary never reads
# them from disk at run time. Each file becomes an entry of a function
# returning a map keyed by the file's name: tofsim::gl::embeddedShaders() for
# the files under shaders/ (e.g. "direct_gather.comp"), and whatever other
# table tofsim_embed_files() is asked for (the viewer's page template).
#
# The generation runs at build time (add_custom_command), so editing a file
# rebuilds the table without re-running CMake's configure step.

set(TOFSIM_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedShadersScript.cmake)

# tofsim_embed_files(<out_var> <namespace> <function> <generated name> <files>...)
function(tofsim_embed_files out_var namespace function generated_name)
  set(embedded_files ${ARGN})
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/${generated_name})
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${generated} "-DFILES=${embedded_files}"
            -DNAMESPACE=${namespace} -DFUNCTION=${function} -P ${TOFSIM_EMBED_SCRIPT}
    DEPENDS ${embedded_files} ${TOFSIM_EMBED_SCRIPT}
    COMMENT "Embedding ${generated_name}"
    VERBATIM)
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction()

function(tofsim_embed_shaders out_var)
  tofsim_embed_files(generated tofsim::gl embeddedShaders EmbeddedShaders.cpp ${ARGN})
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction()
