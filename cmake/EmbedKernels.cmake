# Embeds every file below kernels/ (OpenCL C sources and the headers shared with C++) into one
# generated C++ file: a table of (relative path, text) that engine/device/kernel_sources.cpp reads.
function(gdr_embed_kernels kernel_dir output)
  file(GLOB_RECURSE kernel_files CONFIGURE_DEPENDS ${kernel_dir}/*.cl ${kernel_dir}/*.h)
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DKERNEL_DIR=${kernel_dir} -DOUTPUT=${output}
            -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/EmbedKernelsScript.cmake
    DEPENDS ${kernel_files} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/EmbedKernelsScript.cmake
    COMMENT "Embedding OpenCL kernels"
    VERBATIM)
endfunction()
