# cmake --install: the libraries, their headers under include/opgraph/ (the source tree's folders
# below it, so "core/mesh.h" resolves as in the sources) and the CMake package opgraph
# (opgraphConfig.cmake.in). Test: InstallAndConsume (tests/install_consumer_test.sh).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(OPGRAPH_INCLUDE_DIR ${CMAKE_INSTALL_INCLUDEDIR}/opgraph)
set(OPGRAPH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/opgraph)

# The folders holding the libraries' sources hold their headers.
set(opgraph_header_folders "")
foreach(library IN LISTS OPGRAPH_LIBRARIES)
  get_target_property(sources ${library} SOURCES)
  foreach(source IN LISTS sources)
    get_filename_component(folder ${source} DIRECTORY)
    list(APPEND opgraph_header_folders ${folder})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES opgraph_header_folders)

install(TARGETS ${OPGRAPH_LIBRARIES} EXPORT opgraphTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${OPGRAPH_INCLUDE_DIR} ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${opgraph_header_folders} DESTINATION ${OPGRAPH_INCLUDE_DIR}
  FILES_MATCHING PATTERN "*.h" PATTERN "include" EXCLUDE)
# The entry header, #include <opgraph/opgraph.h>.
install(FILES api/include/opgraph/opgraph.h DESTINATION ${OPGRAPH_INCLUDE_DIR})
install(EXPORT opgraphTargets NAMESPACE opgraph:: DESTINATION ${OPGRAPH_CMAKE_DIR})

configure_package_config_file(cmake/opgraphConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/opgraphConfig.cmake
  INSTALL_DESTINATION ${OPGRAPH_CMAKE_DIR})
# 0.x: a new minor version may change the interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/opgraphConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/opgraphConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/opgraphConfigVersion.cmake
  cmake/opgraphDependencies.cmake
  DESTINATION ${OPGRAPH_CMAKE_DIR})
