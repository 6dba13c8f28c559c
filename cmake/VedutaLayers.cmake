# One static library per source folder (a "layer"), whose link list is the folder's allowed
# arrows in docs/ARCHITECTURE.md ("Layers"). A layer's headers are reachable only through its
# own include root, build/layers/<folder>/<folder> → src/<folder>, which a target sees only
# when it links the layer: an include the graph does not allow fails to compile.
# tests/layers/check_layers.sh checks the same graph against every include and this file.

# The include root of a folder, as an INTERFACE target: for code that needs a layer's
# declarations without its objects (the image plugin implements io's interface).
function(veduta_layer_headers folder)
  set(root ${PROJECT_BINARY_DIR}/layers/${folder})
  file(MAKE_DIRECTORY ${root})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${folder} ${root}/${folder} SYMBOLIC)
  add_library(veduta_${folder}_headers INTERFACE)
  target_include_directories(veduta_${folder}_headers INTERFACE ${root})
  foreach(used ${ARGN})
    target_link_libraries(veduta_${folder}_headers INTERFACE veduta_${used}_headers)
  endforeach()
endfunction()

# veduta_layer(folder SOURCES … USES folder … LIBRARIES external … [PRIVATE_LIBRARIES …])
function(veduta_layer folder)
  cmake_parse_arguments(L "" "" "SOURCES;USES;LIBRARIES;PRIVATE_LIBRARIES" ${ARGN})
  veduta_layer_headers(${folder} ${L_USES})
  add_library(veduta_${folder} STATIC ${L_SOURCES})
  target_link_libraries(veduta_${folder} PUBLIC veduta_${folder}_headers)
  foreach(used ${L_USES})
    target_link_libraries(veduta_${folder} PUBLIC veduta_${used})
  endforeach()
  target_link_libraries(veduta_${folder} PUBLIC ${L_LIBRARIES} PRIVATE ${L_PRIVATE_LIBRARIES})
  target_compile_options(veduta_${folder} PRIVATE ${VEDUTA_WARNINGS})
endfunction()
