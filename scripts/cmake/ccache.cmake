# Compiling through ccache when it is installed (scripts/install-deps.sh installs it with the
# library layer): an object compiled once is reused by any later build of the same source with the
# same flags, in another build tree or another clone of the repository (CI builds a fresh clone
# each time). Paths under the repository are hashed relative to it (base_dir), and the precompiled
# headers are usable only with the pch_defines and time_macros sloppiness (no file of the project
# uses __DATE__ or __TIME__). A launcher of the user's own, or -DCAGD_USE_CCACHE=OFF, turns it off.
# Usage: include(ccache.cmake) after project(), with CAGD_REPOSITORY_ROOT set to the repository.
option(CAGD_USE_CCACHE "compile through ccache when it is installed" ON)
find_program(CAGD_CCACHE_PROGRAM ccache)
mark_as_advanced(CAGD_CCACHE_PROGRAM)
if(CAGD_USE_CCACHE AND CAGD_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER AND NOT DEFINED ENV{CMAKE_CXX_COMPILER_LAUNCHER})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${CAGD_REPOSITORY_ROOT}
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${CAGD_CCACHE_PROGRAM})
endif()

# Definitions whose values differ from clone to clone or from commit to commit (the source tree's
# path, the build tree's, the git revision) go on the few files that read them, compiled outside
# the unity batches: every other file's command line is then the same in every clone, and ccache
# reuses its object. cagd_clone_specific_definitions(FILES f... DEFINITIONS NAME=value...), called
# in the directory whose CMakeLists.txt creates the target.
function(cagd_clone_specific_definitions)
  cmake_parse_arguments(ARG "" "" "FILES;DEFINITIONS" ${ARGN})
  set_source_files_properties(${ARG_FILES} PROPERTIES COMPILE_DEFINITIONS "${ARG_DEFINITIONS}" SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
