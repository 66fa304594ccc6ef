# Helpers that give every fest target the same warnings and sanitizer flags.
# Third-party headers arrive through imported targets with -isystem, so -Werror
# only ever judges fest's own code.

set(FEST_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
if(FEST_WERROR)
  list(APPEND FEST_WARNINGS -Werror)
endif()

if(FEST_FUZZ)
  # Instrument every fest library for coverage and sanitizers, not only the fuzzer's
  # own file: the readers under test live in the libraries.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
elseif(FEST_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# fest_library(NAME ALIAS SOURCES ... ) -- a static library with fest's warnings.
function(fest_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${FEST_WARNINGS})
endfunction()

# fest_plugin(NAME SOURCES ...) -- a module opened with dlopen (formats/plugin_loader.hpp),
# beside the executables in the build tree and in <libdir>/fest when installed. Only its
# entry point is exported, and its own symbols bind inside it (-Bsymbolic), so the code it
# shares with the host (fest_core, header parsers) cannot be interposed either way.
include(GNUInstallDirs)
function(fest_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(${name} PRIVATE ${FEST_WARNINGS})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND (FEST_FUZZ OR FEST_SANITIZE))
    # clang links the sanitizer runtimes into executables only; a module's __asan_* and
    # __sancov_* references resolve against the host when it is opened.
    target_link_options(${name} PRIVATE LINKER:-Bsymbolic)
  else()
    target_link_options(${name} PRIVATE LINKER:--no-undefined LINKER:-Bsymbolic)
  endif()
  set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bin
                        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  install(TARGETS ${name} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/fest)
endfunction()

# fest_tool(NAME SOURCES ...) -- an executable in bin/ with fest's warnings.
function(fest_tool name)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${FEST_WARNINGS})
  target_compile_definitions(${name} PRIVATE FEST_VERSION="${PROJECT_VERSION}")
  install(TARGETS ${name} RUNTIME DESTINATION bin)
endfunction()
