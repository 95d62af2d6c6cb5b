# Installation and the data directory (docs/install.md): what `cmake --install build --prefix P`
# puts where, and the marker that lets a binary of this build tree find this source tree's data.
# The binary looks for its data relative to itself (src/scenario/data_dir.cpp); no path of the build
# or source tree is compiled in. Included after every add_subdirectory (it names their targets).

# Installed layout: P/bin/signalsim and P/share/signalsim/. The binary knows only the relative path.
set(SIGNALSIM_INSTALL_BINDIR bin)
set(SIGNALSIM_INSTALL_DATADIR share/signalsim)
file(RELATIVE_PATH SIGNALSIM_INSTALL_DATA_FROM_BIN
     /prefix/${SIGNALSIM_INSTALL_BINDIR} /prefix/${SIGNALSIM_INSTALL_DATADIR})
set_source_files_properties(src/scenario/data_dir.cpp TARGET_DIRECTORY signalsim_scenario PROPERTIES
  COMPILE_DEFINITIONS SIGNALSIM_INSTALL_DATA_FROM_BIN="${SIGNALSIM_INSTALL_DATA_FROM_BIN}")

# The bundled plugins (the autoware_core decider, src/sut/bundled_plugins.cpp): P/lib/signalsim/plugins
# installed, build/plugins in the build tree (each plugin target's LIBRARY_OUTPUT_DIRECTORY).
set(SIGNALSIM_INSTALL_PLUGINDIR lib/signalsim/plugins)
file(RELATIVE_PATH SIGNALSIM_INSTALL_PLUGINS_FROM_BIN
     /prefix/${SIGNALSIM_INSTALL_BINDIR} /prefix/${SIGNALSIM_INSTALL_PLUGINDIR})
set_source_files_properties(src/sut/bundled_plugins.cpp TARGET_DIRECTORY signalsim_sut PROPERTIES
  COMPILE_DEFINITIONS SIGNALSIM_INSTALL_PLUGINS_FROM_BIN="${SIGNALSIM_INSTALL_PLUGINS_FROM_BIN}")

# The libsumo module (src/session/session_factory.hpp): P/lib/signalsim installed, build/lib/signalsim
# in the build tree (its LIBRARY_OUTPUT_DIRECTORY).
set(SIGNALSIM_INSTALL_MODULEDIR lib/signalsim)
file(RELATIVE_PATH SIGNALSIM_INSTALL_MODULES_FROM_BIN
     /prefix/${SIGNALSIM_INSTALL_BINDIR} /prefix/${SIGNALSIM_INSTALL_MODULEDIR})
set_source_files_properties(src/session/session_factory.cpp TARGET_DIRECTORY signalsim_session PROPERTIES
  COMPILE_DEFINITIONS SIGNALSIM_INSTALL_MODULES_FROM_BIN="${SIGNALSIM_INSTALL_MODULES_FROM_BIN}")
install(TARGETS signalsim_libsumo LIBRARY DESTINATION ${SIGNALSIM_INSTALL_MODULEDIR})

# Build tree: one line naming the source tree, found by walking up from the binary's folder. It is
# not installed, so an installed binary never reads this tree.
file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/signalsim-data-dir.txt CONTENT "${PROJECT_SOURCE_DIR}\n")

# SUMO outside the system's library folders (a SUMO_HOME build) stays found by the installed binary.
set_target_properties(signalsim PROPERTIES INSTALL_RPATH_USE_LINK_PATH TRUE)

install(TARGETS signalsim RUNTIME DESTINATION ${SIGNALSIM_INSTALL_BINDIR})
install(DIRECTORY config DESTINATION ${SIGNALSIM_INSTALL_DATADIR})
# The table of Autoware's keys of its parameter files (--strict-params; tools/autoware_key_tables).
install(DIRECTORY data DESTINATION ${SIGNALSIM_INSTALL_DATADIR})
# The plot program (run --plot, sweep --plot, compare --plot, the HTML report) and its package, product beside the
# binary: python/ of the source tree is python/ of the data directory (src/app/plot_tool.cpp).
install(PROGRAMS python/signalsim-plot DESTINATION ${SIGNALSIM_INSTALL_DATADIR}/python)
install(DIRECTORY python/signalsim_plot DESTINATION ${SIGNALSIM_INSTALL_DATADIR}/python
        FILES_MATCHING PATTERN "*.py" PATTERN "*.js" PATTERN "*.css" PATTERN __pycache__ EXCLUDE)  # the report's script and style
# The bundled suite and its nets (scenarios name ../config and ../sumo_nets). scenarios/sweeps is
# left out: its sweep names the test data (tests/data), which is not installed.
install(DIRECTORY scenarios DESTINATION ${SIGNALSIM_INSTALL_DATADIR} PATTERN sweeps EXCLUDE)
install(DIRECTORY sumo_nets DESTINATION ${SIGNALSIM_INSTALL_DATADIR})

# The plugin ABI's header, for plugins built against an installation (docs/decider.md "The C ABI").
install(FILES include/signalsim/decider_plugin.h DESTINATION include/signalsim)
# The bundled plugins, wherever their targets are added (called once the top directory is read).
function(signalsim_install_bundled_plugins)
  foreach(plugin IN ITEMS signalsim_autoware_core)
    if(TARGET ${plugin})
      install(TARGETS ${plugin} LIBRARY DESTINATION ${SIGNALSIM_INSTALL_PLUGINDIR})
    endif()
  endforeach()
endfunction()
cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL signalsim_install_bundled_plugins)
