# SPDX-License-Identifier: MIT
# stroma_add_plugin(<Name> SOURCES <files...> [LIBRARIES <targets...>] [NO_INSTALL])
#
# Builds a Stroma plugin: a shared library in the plugin directory, plus its index file
# <Name>.stroma-plugin, written right after the build by `stroma plugin-index`, that lists the
# components it provides. Scenes then load the plugin only when they use one of them.
# Used for the built-in plugins and, through find_package(Stroma), for external ones.
function(stroma_add_plugin name)
  cmake_parse_arguments(ARG "NO_INSTALL" "OUTPUT_DIRECTORY" "SOURCES;LIBRARIES" ${ARGN})
  if(TARGET stroma)
    set(cli $<TARGET_FILE:stroma>)
    set(framework StromaFramework)
  else()
    set(cli $<TARGET_FILE:Stroma::stroma>)
    set(framework Stroma::Framework)
  endif()
  if(ARG_OUTPUT_DIRECTORY)
    set(outdir ${ARG_OUTPUT_DIRECTORY})
  elseif(DEFINED STROMA_PLUGIN_OUTPUT_DIR)
    set(outdir ${STROMA_PLUGIN_OUTPUT_DIR})
  else()
    set(outdir ${CMAKE_CURRENT_BINARY_DIR}/plugins)
  endif()
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${framework} ${ARG_LIBRARIES})
  if(TARGET stroma_options)
    target_link_libraries(${name} PRIVATE stroma_options)
  endif()
  set_target_properties(${name} PROPERTIES
    PREFIX "lib" LIBRARY_OUTPUT_DIRECTORY ${outdir}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
    INSTALL_RPATH "$ORIGIN/../..")
  add_custom_command(TARGET ${name} POST_BUILD
    COMMAND ${cli} plugin-index $<TARGET_FILE:${name}> --output ${outdir}/${name}.stroma-plugin
    COMMENT "Indexing the components of plugin ${name}" VERBATIM)
  if(TARGET stroma)
    add_dependencies(${name} stroma)
  endif()
  if(NOT ARG_NO_INSTALL AND DEFINED STROMA_PLUGIN_INSTALL_DIR)
    install(TARGETS ${name} LIBRARY DESTINATION ${STROMA_PLUGIN_INSTALL_DIR})
    install(FILES ${outdir}/${name}.stroma-plugin DESTINATION ${STROMA_PLUGIN_INSTALL_DIR})
  endif()
endfunction()

# stroma_add_unavailable_plugin(<Name> REASON <text> COMPONENTS_FILE <file>)
#
# A plugin this build leaves out because a library it needs is missing: writes its index with an
# `unavailable` line (REASON: what is missing and what to install) and the components listed in
# COMPONENTS_FILE (one per line, '#' comments), so that a scene using one of them is told why
# it cannot be created instead of hearing of an unknown component.
function(stroma_add_unavailable_plugin name)
  cmake_parse_arguments(ARG "" "REASON;COMPONENTS_FILE" "" ${ARGN})
  set(outdir ${STROMA_PLUGIN_OUTPUT_DIR})
  file(STRINGS ${ARG_COMPONENTS_FILE} lines)
  set(text "# Stroma plugin index, written at configure time: this build left the plugin out.\n")
  string(APPEND text "plugin ${name}\nunavailable ${ARG_REASON}\n")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    if(line AND NOT line MATCHES "^#")
      string(APPEND text "component ${line}\n")
    endif()
  endforeach()
  file(WRITE ${outdir}/${name}.stroma-plugin "${text}")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ARG_COMPONENTS_FILE})
  if(DEFINED STROMA_PLUGIN_INSTALL_DIR)
    install(FILES ${outdir}/${name}.stroma-plugin DESTINATION ${STROMA_PLUGIN_INSTALL_DIR})
  endif()
  message(STATUS "Plugin ${name} left out: ${ARG_REASON}")
endfunction()
