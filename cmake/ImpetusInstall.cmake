# The engine as an installed library (README.md, "The engine as a library"): its headers under
# include/impetus/, its static libraries, and a CMake package so that another project can write
#   find_package(Impetus 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE impetus::engine)
# Included by the top-level CMakeLists.txt after src/ is added, so the targets exist.

include(CMakePackageConfigHelpers)

# impetus_install_headers(TARGET): installs the headers among TARGET's sources, which lie under
# src/<dir>, to include/impetus/<dir>/ with their subfolders, so that an installed program includes
# "model/world.h" and "controller/simulation.h" just as the engine's own sources do. Taken from the
# target's source list, so a header added there is installed with no edit here.
function(impetus_install_headers target)
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  file(RELATIVE_PATH dir ${PROJECT_SOURCE_DIR}/src ${source_dir})
  foreach(source IN LISTS sources)
    if(source MATCHES "\\.h$")
      get_filename_component(subdir ${source} DIRECTORY)
      install(FILES ${source_dir}/${source}
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impetus/${dir}/${subdir})
    endif()
  endforeach()
endfunction()

# impetus::engine: the whole engine in one name, for programs that do not care about the split.
add_library(impetus_engine INTERFACE)
add_library(impetus::engine ALIAS impetus_engine)
target_link_libraries(impetus_engine INTERFACE impetus_controller impetus_model)

# Exported as impetus::model, impetus::controller and impetus::engine, the names the build tree
# uses (the ALIAS targets), so code moves between the two unchanged.
set_target_properties(impetus_model PROPERTIES EXPORT_NAME model)
set_target_properties(impetus_controller PROPERTIES EXPORT_NAME controller)
set_target_properties(impetus_engine PROPERTIES EXPORT_NAME engine)

impetus_install_headers(impetus_model)
impetus_install_headers(impetus_controller)
install(TARGETS impetus_model impetus_controller impetus_engine
  EXPORT ImpetusTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

set(impetus_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Impetus)
install(EXPORT ImpetusTargets NAMESPACE impetus:: DESTINATION ${impetus_package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ImpetusConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ImpetusConfig.cmake
  INSTALL_DESTINATION ${impetus_package_dir})
# Before 1.0 a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ImpetusConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ImpetusConfig.cmake ${PROJECT_BINARY_DIR}/ImpetusConfigVersion.cmake
  DESTINATION ${impetus_package_dir})
