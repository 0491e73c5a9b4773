# ballsight_target_defaults(<target>): the project's warning set, applied to every target we own.
function(ballsight_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wnon-virtual-dtor)
  if(BALLSIGHT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# ballsight_sanitized(<target>): AddressSanitizer and UndefinedBehaviorSanitizer on the target's
# code (BALLSIGHT_SANITIZE); a finding ends the program, so that a test fails on it. -g1: file and
# line in the reports.
function(ballsight_sanitized target)
  # GCC 12 with these flags takes Asio's coroutine frames (boost::asio::awaitable, the HTTP
  # server) for a mismatched new and delete: a false positive; a real one would show in ASan.
  target_compile_options(${target} PRIVATE -fsanitize=address,undefined -g1
                                           -fno-sanitize-recover=all -Wno-mismatched-new-delete)
  # Every program that links the target gets the sanitizers' runtime (and LeakSanitizer's check at
  # exit); the ones that do not, such as the Fast DDS reader of the tests, stay as they are.
  target_link_options(${target} PUBLIC -fsanitize=address,undefined)
endfunction()

# ballsight_layer(<name> SOURCES ... DEPS ...): one static library per ARCHITECTURE.md layer.
# A layer without .cpp files is header-only (an INTERFACE library). Its files are compiled a few
# at a time (the headers, OpenCV, Eigen, JSON, Asio, are most of a file's compile time).
function(ballsight_layer name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  set_property(GLOBAL APPEND PROPERTY BALLSIGHT_LAYERS ${name})
  set_property(GLOBAL PROPERTY BALLSIGHT_LAYER_${name}_SOURCES ${ARG_SOURCES})
  set_property(GLOBAL PROPERTY BALLSIGHT_LAYER_${name}_DEPS ${ARG_DEPS})
  if(ARG_SOURCES)
    add_library(ballsight_${name} STATIC ${ARG_SOURCES})
    target_include_directories(ballsight_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(ballsight_${name} PUBLIC ${ARG_DEPS})
    ballsight_target_defaults(ballsight_${name})
    set_target_properties(ballsight_${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6)
  else()
    add_library(ballsight_${name} INTERFACE)
    target_include_directories(ballsight_${name} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(ballsight_${name} INTERFACE ${ARG_DEPS})
  endif()
  add_library(ballsight::${name} ALIAS ballsight_${name})
endfunction()

# ballsight_sanitized_names(<list>): in the list variable, every ballsight::<layer> becomes
# ballsight_<layer>_sanitized (ballsight_sanitized_layers).
function(ballsight_sanitized_names list)
  list(TRANSFORM ${list} REPLACE "^ballsight::(.*)$" "ballsight_\\1_sanitized")
  set(${list} ${${list}} PARENT_SCOPE)
endfunction()

# ballsight_sanitized_layers(): with BALLSIGHT_SANITIZE, ballsight_<layer>_sanitized for every
# layer, what the unit tests of the sanitized layers link: a second build of each layer of
# BALLSIGHT_SANITIZED_LAYERS with the sanitizers (at -O1, the sanitizers' usual level), and for
# the other layers their ordinary library, so that a test of calib, say, runs the sanitized calib,
# camera and core under the ordinary simulator. The command and every other test link the
# ordinary libraries: instrumented, the simulator's rendering made the whole suite three times
# slower (docs/RESULTS.md, "Sanitizers"). The ordinary copies are imported archives that carry
# their layer's dependencies, so that CMake puts every archive before the ones it needs (a plain
# archive file could not be ordered: with service/ and robot/ beside pipeline/, test_net's link
# put the world layer before the pipeline's archive). Call it after the last ballsight_layer().
function(ballsight_sanitized_layers)
  get_property(layers GLOBAL PROPERTY BALLSIGHT_LAYERS)
  foreach(name ${layers})
    get_property(sources GLOBAL PROPERTY BALLSIGHT_LAYER_${name}_SOURCES)
    get_property(deps GLOBAL PROPERTY BALLSIGHT_LAYER_${name}_DEPS)
    ballsight_sanitized_names(deps)
    set(copy ballsight_${name}_sanitized)
    if(sources AND name IN_LIST BALLSIGHT_SANITIZED_LAYERS)
      add_library(${copy} STATIC EXCLUDE_FROM_ALL ${sources})
      target_include_directories(${copy} PUBLIC ${PROJECT_SOURCE_DIR}/src)
      target_link_libraries(${copy} PUBLIC ${deps})
      ballsight_target_defaults(${copy})
      ballsight_sanitized(${copy})
      target_compile_options(${copy} PRIVATE -O1)
      set_target_properties(${copy} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 6
                                               BALLSIGHT_SANITIZED ON)
    elseif(sources)  # the ordinary library's archive, with its dependencies for the linker
      add_library(${copy} STATIC IMPORTED GLOBAL)
      get_target_property(dir ballsight_${name} BINARY_DIR)
      set_target_properties(${copy} PROPERTIES
        IMPORTED_LOCATION
          ${dir}/${CMAKE_STATIC_LIBRARY_PREFIX}ballsight_${name}${CMAKE_STATIC_LIBRARY_SUFFIX}
        INTERFACE_LINK_LIBRARIES "${deps}"
        INTERFACE_INCLUDE_DIRECTORIES ${PROJECT_SOURCE_DIR}/src)
    else()  # a header-only layer
      add_library(${copy} INTERFACE)
      target_link_libraries(${copy} INTERFACE ${deps})
      target_include_directories(${copy} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    endif()
  endforeach()
endfunction()
