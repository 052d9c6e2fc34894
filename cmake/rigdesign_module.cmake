# One static library per module (issue 51 item 1), linked along the "uses" column of
# docs/DESIGN.md section 2, and a link check that makes the column binding: the check links
# every object file of the module (whole archive) against the modules it uses and nothing
# else, so a call into a module it may not use is an undefined reference at build time.
# tests/layering/check_layers.py stays as the second guard, on includes.

# rigdesign_module(NAME [USES module...] [LIBS target...]) makes rigdesign_NAME (sources added
# by the module's own CMakeLists.txt with target_sources) and its link check.
function(rigdesign_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "USES;LIBS")
  add_library(rigdesign_${name} STATIC)
  add_library(rigdesign::${name} ALIAS rigdesign_${name})
  target_include_directories(rigdesign_${name} PUBLIC ${PROJECT_SOURCE_DIR}/include
                                               PRIVATE ${PROJECT_SOURCE_DIR}/src)
  set(used "")
  foreach(module IN LISTS arg_USES)
    list(APPEND used rigdesign_${module})
  endforeach()
  target_link_libraries(rigdesign_${name} PUBLIC Eigen3::Eigen ${used}
                        PRIVATE ${arg_LIBS} rigdesign_warnings)
  rigdesign_link_check(${name})
endfunction()

# rigdesign_link_check(NAME): an executable holding all of rigdesign_NAME's objects, linked with
# what the library itself links. It is built, never run.
function(rigdesign_link_check name)
  set(main ${CMAKE_CURRENT_BINARY_DIR}/link_check_main.cpp)
  if(NOT EXISTS ${main})
    file(WRITE ${main} "// Built to prove a module links alone (cmake/rigdesign_module.cmake).\n"
                       "int main() { return 0; }\n")
  endif()
  add_executable(rigdesign_link_check_${name} ${main})
  target_link_libraries(rigdesign_link_check_${name}
                        PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,rigdesign_${name}>" rigdesign_warnings)
endfunction()
