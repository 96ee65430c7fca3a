# The library's layers (DESIGN.md): one target per layer, each linking only the layers it may
# use, and the list of what each layer may #include, which the test
# layers_include_only_the_layers_below checks (cmake/CheckLayers.cmake) over include/impetus/<layer>/
# and src/<layer>/. A layer may include itself, the layers it USES and everything those may.
# `math` is header-only and has no target; the top-level headers (impetus/error.hpp,
# impetus/version.hpp) belong to core.

# The layers' target names: impetus_<layer>, but impetus_geo_core and impetus_audio_core, since
# impetus::geo and impetus::audio are the optional back-ends (GeographicLib, OpenAL Soft).
function(impetus_layer_target out layer)
  if(layer STREQUAL "geo" OR layer STREQUAL "audio")
    set(${out} impetus_${layer}_core PARENT_SCOPE)
  else()
    set(${out} impetus_${layer} PARENT_SCOPE)
  endif()
endfunction()

# impetus_add_layer(<layer> USES <layer>... [SOURCES <file>...]): the layer's target (an
# INTERFACE library when it has no sources), linked to the targets of the layers it uses;
# appends it to the global property IMPETUS_LAYER_TARGETS and records what it may include in
# the global property IMPETUS_LAYERS ("layer:allowed,allowed,...").
function(impetus_add_layer layer)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "USES;SOURCES")
  impetus_layer_target(target ${layer})
  set(allowed ${layer})
  set(deps)
  foreach(used IN LISTS arg_USES)
    get_property(used_allowed GLOBAL PROPERTY IMPETUS_LAYER_ALLOWED_${used})
    list(APPEND allowed ${used} ${used_allowed})
    if(NOT used STREQUAL "math")
      impetus_layer_target(used_target ${used})
      list(APPEND deps ${used_target})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set_property(GLOBAL PROPERTY IMPETUS_LAYER_ALLOWED_${layer} ${allowed})
  list(JOIN allowed "," allowed_text)
  set_property(GLOBAL APPEND PROPERTY IMPETUS_LAYERS "${layer}:${allowed_text}")

  if(arg_SOURCES)
    set(scope PUBLIC)
    add_library(${target} STATIC ${arg_SOURCES})
    target_link_libraries(${target} PUBLIC ${deps})
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}) # src/: internal headers
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    impetus_target_settings(${target})
  else()
    set(scope INTERFACE)
    add_library(${target} INTERFACE)
    target_link_libraries(${target} INTERFACE ${deps})
  endif()
  if(NOT deps)
    # The bottom layer carries the public headers and the language level for everyone.
    target_include_directories(${target} ${scope}
      $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_compile_features(${target} ${scope} cxx_std_20)
  endif()
  string(REPLACE "impetus_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  add_library(impetus::${export_name} ALIAS ${target})
  set_property(GLOBAL APPEND PROPERTY IMPETUS_LAYER_TARGETS ${target})
endfunction()
