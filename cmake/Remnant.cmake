# Build conventions of Remnant: thorns, their tests and benchmarks, and executables composed from
# schedules/<exe>.yaml. Read DESIGN.md section 2 for the layout.

# remnant_thorn(<Name> SOURCES <files...> [LIBS <targets...>])
# Creates the static library thorn_<Name> from thorns/<Name>/. Public headers live in
# thorns/<Name>/include/<Name>/ and are included as <Name/header.hpp>. The sources must define
# REMNANT_REGISTER_THORN(<Name>) (see framework/include/remnant/registrar.hpp).
function(remnant_thorn name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  set(target thorn_${name})
  add_library(${target} STATIC ${ARG_SOURCES})
  target_link_libraries(${target} PUBLIC remnant_flesh ${ARG_LIBS})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  endif()
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  set(yaml ${CMAKE_CURRENT_SOURCE_DIR}/thorn.yaml)
  if(NOT EXISTS ${yaml})
    message(FATAL_ERROR "thorn ${name}: ${yaml} is missing")
  endif()
  set_property(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${yaml})
  _remnant_thorn_views(${name} ${target} ${yaml})
  file(READ ${yaml} text)
  if(NOT text MATCHES "(^|\n)thorn:[ \t]*${name}[ \t]*(#[^\n]*)?(\n|$)")
    message(FATAL_ERROR "${yaml}: the 'thorn:' key must be '${name}', the folder's name")
  endif()
  _remnant_flow_list("${text}" provides provides)
  _remnant_flow_list("${text}" requires requires)
  set_property(GLOBAL APPEND PROPERTY REMNANT_THORNS ${name})
  set_property(GLOBAL PROPERTY REMNANT_THORN_${name}_YAML ${yaml})
  set_property(GLOBAL PROPERTY REMNANT_THORN_${name}_PROVIDES "${provides}")
  set_property(GLOBAL PROPERTY REMNANT_THORN_${name}_REQUIRES "${requires}")
endfunction()

# Named views: <remnant/vars/<Name>.hpp> is generated from thorn.yaml by remnant-genviews. Every
# thorn library sees every thorn's header (GRMHD reads Spacetime::metric through it), so each
# waits for all of them (the target remnant_views, made in the top-level CMakeLists.txt).
function(_remnant_thorn_views name target yaml)
  set(dir ${CMAKE_BINARY_DIR}/generated/views)
  set(header ${dir}/remnant/vars/${name}.hpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/views_${name}.stamp)
  file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${yaml})
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}/remnant/vars
    COMMAND remnant-genviews ${yaml} ${header} ${rel}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    BYPRODUCTS ${header}
    DEPENDS ${yaml} remnant-genviews
    COMMENT "Generating the named views of ${name} from ${rel}")
  add_custom_target(views_${name} DEPENDS ${stamp})
  set_property(GLOBAL APPEND PROPERTY REMNANT_VIEW_TARGETS views_${name})
  target_include_directories(${target} PUBLIC ${dir})
  add_dependencies(${target} remnant_views)
endfunction()

# Parses `key: [a, b, c]` (the list may span lines) from a YAML text; empty when absent.
function(_remnant_flow_list text key out)
  set(result "")
  if(text MATCHES "(^|\n)${key}:[ \t]*\\[([^]]*)\\]")
    string(REGEX REPLACE "[ \t\r\n]" "" inner "${CMAKE_MATCH_2}")
    if(NOT inner STREQUAL "")
      string(REPLACE "," ";" result "${inner}")
    endif()
  elseif(text MATCHES "(^|\n)${key}:[ \t]*[^ \t\n#]")
    message(FATAL_ERROR "'${key}:' must be a flow list such as '${key}: [a, b]'")
  endif()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# Checks that every capability required by the thorns is provided exactly once.
function(_remnant_check_capabilities context thorns)
  set(all_caps "")
  foreach(t ${thorns})
    get_property(p GLOBAL PROPERTY REMNANT_THORN_${t}_PROVIDES)
    foreach(c ${p})
      if(DEFINED provider_${c})
        message(FATAL_ERROR "${context}: capability '${c}' is provided by two thorns: "
                            "${provider_${c}} and ${t}. Keep only one of them in the thorn list.")
      endif()
      set(provider_${c} ${t})
    endforeach()
  endforeach()
  foreach(t ${thorns})
    get_property(r GLOBAL PROPERTY REMNANT_THORN_${t}_REQUIRES)
    foreach(c ${r})
      if(NOT DEFINED provider_${c})
        set(candidates "")
        get_property(known GLOBAL PROPERTY REMNANT_THORNS)
        foreach(k ${known})
          get_property(kp GLOBAL PROPERTY REMNANT_THORN_${k}_PROVIDES)
          if(c IN_LIST kp)
            list(APPEND candidates ${k})
          endif()
        endforeach()
        if(candidates)
          string(REPLACE ";" ", " candidates "${candidates}")
          set(hint " Thorns that provide it: ${candidates}.")
        else()
          set(hint " No known thorn provides it.")
        endif()
        message(FATAL_ERROR "${context}: thorn ${t} requires capability '${c}', which no thorn "
                            "in the list provides.${hint}")
      endif()
    endforeach()
  endforeach()
endfunction()

# Writes a C++ source holding the thorn table (embedded thorn.yaml texts and register functions).
function(_remnant_write_thorn_table out_file context thorns)
  set(decls "")
  set(entries "")
  foreach(t ${thorns})
    get_property(known GLOBAL PROPERTY REMNANT_THORNS)
    if(NOT t IN_LIST known)
      string(REPLACE ";" ", " known_str "${known}")
      message(FATAL_ERROR "${context}: unknown thorn '${t}'. Known thorns: ${known_str}")
    endif()
    get_property(yaml GLOBAL PROPERTY REMNANT_THORN_${t}_YAML)
    file(READ ${yaml} text)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${yaml})
    string(APPEND decls "void remnant_register_thorn_${t}(remnant::ThornRegistrar&);\n")
    string(APPEND entries "  {\"${t}\", \"${rel}\", R\"REMNANT_YAML(${text})REMNANT_YAML\", &remnant_register_thorn_${t}},\n")
  endforeach()
  set(content "// Generated by cmake/Remnant.cmake from ${context}; do not edit.\n#include <remnant/thorn_table.hpp>\n\n${decls}\nnamespace {\nconst remnant::ThornEntry kThorns[] = {\n${entries}};\n}\n\nstd::span<const remnant::ThornEntry> remnant_compiled_thorns() { return kThorns; }\n")
  file(CONFIGURE OUTPUT ${out_file} CONTENT "${content}" @ONLY)
endfunction()

function(_remnant_embed_text out_file symbol path)
  file(READ ${CMAKE_SOURCE_DIR}/${path} text)
  file(CONFIGURE OUTPUT ${out_file} CONTENT
       "// Generated; do not edit.\n#include <remnant/thorn_table.hpp>\nextern const remnant::EmbeddedText ${symbol};\nconst remnant::EmbeddedText ${symbol}{\"${path}\", R\"REMNANT_YAML(${text})REMNANT_YAML\"};\n" @ONLY)
endfunction()

# One executable per schedules/<exe>.yaml:  executable, thorns: [..], default_parfile.
function(remnant_add_executable_from_schedule sched)
  set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${sched})
  file(READ ${sched} text)
  file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${sched})
  if(NOT text MATCHES "(^|\n)executable:[ \t]*([A-Za-z0-9_.-]+)")
    message(FATAL_ERROR "${rel}: missing 'executable: <name>'")
  endif()
  set(exe ${CMAKE_MATCH_2})
  _remnant_flow_list("${text}" thorns thorns)
  if(NOT thorns)
    message(FATAL_ERROR "${rel}: missing 'thorns: [..]'")
  endif()
  _remnant_check_capabilities("${rel}" "${thorns}")
  set(gen ${CMAKE_BINARY_DIR}/generated/${exe})
  _remnant_write_thorn_table(${gen}/thorn_table.cpp "${rel}" "${thorns}")
  set(default_parfile "")
  if(text MATCHES "(^|\n)default_parfile:[ \t]*([^ \t\n#]+)")
    set(default_parfile ${CMAKE_MATCH_2})
    set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                 ${CMAKE_SOURCE_DIR}/${default_parfile})
    file(READ ${CMAKE_SOURCE_DIR}/${default_parfile} default_text)
    if(default_text MATCHES "(^|\n)include:")
      message(FATAL_ERROR "${rel}: the default parfile ${default_parfile} is embedded in the executable and "
                          "must not include other parfiles")
    endif()
    _remnant_embed_text(${gen}/default_parfile.cpp remnant_default_parfile ${default_parfile})
  else()
    file(CONFIGURE OUTPUT ${gen}/default_parfile.cpp CONTENT
         "#include <remnant/thorn_table.hpp>\nextern const remnant::EmbeddedText remnant_default_parfile;\nconst remnant::EmbeddedText remnant_default_parfile{\"\", \"\"};\n")
  endif()
  file(CONFIGURE OUTPUT ${gen}/main.cpp CONTENT
       "// Generated; do not edit.\n#include <remnant/driver.hpp>\n#include <remnant/thorn_table.hpp>\nstd::span<const remnant::ThornEntry> remnant_compiled_thorns();\nextern const remnant::EmbeddedText remnant_default_parfile;\nint main(int argc, char** argv) {\n  return remnant::run_main(argc, argv, {\"${exe}\", \"${rel}\", remnant_compiled_thorns(), remnant_default_parfile});\n}\n")
  add_executable(${exe} ${gen}/main.cpp ${gen}/thorn_table.cpp ${gen}/default_parfile.cpp)
  foreach(t ${thorns})
    target_link_libraries(${exe} PRIVATE thorn_${t})
  endforeach()
  set_property(GLOBAL APPEND PROPERTY REMNANT_EXECUTABLES ${exe})
endfunction()

# remnant_thorn_tests(<Name> SOURCES <files...> [THORNS <thorns...>] [LIBS <targets...>] [LABELS <labels...>])
# A GoogleTest program test_<Name>, labelled <Name> in CTest. With THORNS, the test links those
# thorns and a thorn table (remnant_compiled_thorns()) so that it can run whole simulations. With
# LABELS (e.g. long), the program is one CTest test <Name> labelled <Name> and LABELS.
function(remnant_thorn_tests name)
  if(NOT REMNANT_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;THORNS;LIBS;LABELS" ${ARGN})
  set(target test_${name})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE remnant_test_main GTest::gtest ${ARG_LIBS})
  if(TARGET thorn_${name})
    target_link_libraries(${target} PRIVATE thorn_${name})
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  endif()
  target_compile_definitions(${target} PRIVATE
    REMNANT_SOURCE_DIR="${CMAKE_SOURCE_DIR}" REMNANT_SHARED_EOS_DIR="${CMAKE_SOURCE_DIR}/../shared/eos")
  if(ARG_THORNS)
    # Thorn folders are added in sorted order: link the thorn list once every thorn is known.
    cmake_language(EVAL CODE
      "cmake_language(DEFER DIRECTORY \"${CMAKE_SOURCE_DIR}\" CALL _remnant_link_test_thorns \"${target}\" \"${name}\" ${ARG_THORNS})")
  endif()
  if(ARG_LABELS)
    add_test(NAME ${name} COMMAND ${target} WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    set_tests_properties(${name} PROPERTIES LABELS "${name};${ARG_LABELS}")
    return()
  endif()
  gtest_discover_tests(${target} PROPERTIES LABELS "${name}" DISCOVERY_TIMEOUT 60
                       WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
endfunction()

function(_remnant_link_test_thorns target name)
  set(thorns ${ARGN})
  _remnant_check_capabilities("tests of ${name}" "${thorns}")
  set(gen ${CMAKE_BINARY_DIR}/generated/${target})
  _remnant_write_thorn_table(${gen}/thorn_table.cpp "tests of ${name}" "${thorns}")
  target_sources(${target} PRIVATE ${gen}/thorn_table.cpp)
  foreach(t ${thorns})
    target_link_libraries(${target} PRIVATE thorn_${t})
  endforeach()
endfunction()

# remnant_test_needs(<Name> <targets...>): programs that tests labelled <Name> run besides test_<Name>
# (a second MPI test program, a benchmark, a command-line tool). `--target test_<Name>` builds them,
# so that a partial build passes its thorn's label.
function(remnant_test_needs name)
  if(TARGET test_${name})
    add_dependencies(test_${name} ${ARGN})
  endif()
endfunction()

# remnant_thorn_bench(<Name> SOURCES <files...> [LIBS ...]): a Google Benchmark program bench_<Name>.
function(remnant_thorn_bench name)
  if(NOT REMNANT_BUILD_BENCHMARKS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  set(target bench_${name})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE benchmark::benchmark ${ARG_LIBS})
  if(TARGET thorn_${name})
    target_link_libraries(${target} PRIVATE thorn_${name})
    target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  endif()
  target_compile_definitions(${target} PRIVATE
    REMNANT_SOURCE_DIR="${CMAKE_SOURCE_DIR}" REMNANT_SHARED_EOS_DIR="${CMAKE_SOURCE_DIR}/../shared/eos")
  # Smoke test: every benchmark once, briefly (a benchmark that crashes or aborts fails the suite;
  # the timings themselves are not tested).
  if(REMNANT_BUILD_TESTS)
    add_test(NAME bench.${name}.smoke COMMAND ${target} --benchmark_min_time=0.0001)
    set_tests_properties(bench.${name}.smoke PROPERTIES LABELS "bench;${name}" TIMEOUT 300)
    remnant_test_needs(${name} ${target})
  endif()
endfunction()

# Regression suites: testsuites/<Thorn>/<test>/test.yaml, each run on 1 and 2 MPI ranks.
function(remnant_add_regression_tests)
  file(GLOB suite_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/testsuites/*/*/test.yaml)
  list(SORT suite_files)
  set(suites "")
  foreach(f ${suite_files})
    get_filename_component(d ${f} DIRECTORY)
    list(APPEND suites ${d})
  endforeach()
  # Debian's python3 has the numpy/h5py/yaml packages that utils/ scripts use.
  find_program(REMNANT_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
  if(NOT REMNANT_PYTHON)
    find_program(REMNANT_PYTHON NAMES python3 REQUIRED)
  endif()
  foreach(dir ${suites})
    if(NOT EXISTS ${dir}/test.yaml)
      continue()
    endif()
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${dir})
    string(REGEX MATCH "^testsuites/([^/]+)/" _ ${rel})
    set(thorn ${CMAKE_MATCH_1})
    # The rank counts of the suite's `nprocs:` (1 and 2 when it has none).
    set(nps 1 2)
    file(STRINGS ${dir}/test.yaml nprocs_line REGEX "^nprocs:")
    if(nprocs_line)
      string(REGEX MATCHALL "[0-9]+" nps "${nprocs_line}")
    endif()
    foreach(np ${nps})
      add_test(NAME regression:${rel}:np${np}
               COMMAND ${REMNANT_PYTHON} ${CMAKE_SOURCE_DIR}/utils/run_testsuites
                       --build-dir ${CMAKE_BINARY_DIR} --np ${np} ${dir})
      set_tests_properties(regression:${rel}:np${np} PROPERTIES LABELS "regression;${thorn}"
                           PROCESSORS ${np} SKIP_REGULAR_EXPRESSION "REMNANT_TEST_SKIPPED")
    endforeach()
  endforeach()
endfunction()
