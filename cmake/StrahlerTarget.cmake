# Shared compile settings for every strahler target.
function(strahler_configure_target target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wconversion -Wshadow
    # GCC 12 reports false positives at -O2 through std::variant (our Result) and
    # std::string concatenation (GCC bug 105329). Clang (the fuzz preset) has neither option.
    $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized> $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>
    # Bit-identical results on every machine: no fused multiply-add contraction.
    -ffp-contract=off)
  if(STRAHLER_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# A core module: core/<name>/{include,src}, target strahler_<name>, alias strahler::<name>.
function(strahler_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(strahler_${name} STATIC ${ARG_SOURCES})
  add_library(strahler::${name} ALIAS strahler_${name})
  target_include_directories(strahler_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(strahler_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  strahler_configure_target(strahler_${name})
endfunction()
