# ballsight_target_defaults(<target>): the project's warning set, applied to every target we own.
function(ballsight_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(BALLSIGHT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# ballsight_sanitized(<target>): AddressSanitizer and UndefinedBehaviorSanitizer on the target's
# code (BALLSIGHT_SANITIZE); a finding ends the program, so that a test fails on it.
function(ballsight_sanitized target)
  # GCC 12 with these flags takes Asio's coroutine frames (boost::asio::awaitable, the HTTP
  # server) for a mismatched new and delete: a false positive; a real one would show in ASan.
  target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                           -fno-sanitize-recover=all -Wno-mismatched-new-delete)
endfunction()

# ballsight_layer(<name> SOURCES ... DEPS ...): one static library per ARCHITECTURE.md layer.
# A layer without .cpp files is header-only (an INTERFACE library).
function(ballsight_layer name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  if(ARG_SOURCES)
    add_library(ballsight_${name} STATIC ${ARG_SOURCES})
    target_include_directories(ballsight_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(ballsight_${name} PUBLIC ${ARG_DEPS})
    ballsight_target_defaults(ballsight_${name})
    if(name IN_LIST BALLSIGHT_SANITIZED_LAYERS)
      ballsight_sanitized(ballsight_${name})
    endif()
  else()
    add_library(ballsight_${name} INTERFACE)
    target_include_directories(ballsight_${name} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(ballsight_${name} INTERFACE ${ARG_DEPS})
  endif()
  add_library(ballsight::${name} ALIAS ballsight_${name})
endfunction()
