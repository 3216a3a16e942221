# `cmake --install BUILD --prefix P` installs the command and the library as the CMake package
# `ncverify`: another project finds it with find_package(ncverify) (CMAKE_PREFIX_PATH=P) and
# links ncverify::ncverify (README.md "The library"; examples/ is such a project).
include(CMakePackageConfigHelpers)

install(TARGETS ncverify RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ncverify_core EXPORT ncverifyTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The public header includes src/'s headers by their stage folder ("runners/..."), so they
# go beside it; include/ncverify is on the package's include path for them.
install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/include/ncverify/verify.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ncverify)
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ncverify
        FILES_MATCHING PATTERN "*.hpp")

set(NCV_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ncverify)
install(EXPORT ncverifyTargets NAMESPACE ncverify:: DESTINATION ${NCV_PACKAGE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ncverifyConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/ncverifyConfig.cmake
                              INSTALL_DESTINATION ${NCV_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ncverifyConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ncverifyConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/ncverifyConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindxxHash.cmake
        DESTINATION ${NCV_PACKAGE_DIR})
