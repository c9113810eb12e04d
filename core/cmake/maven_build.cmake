# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#
# maven_build(OUTPUT [MAVEN_ARGS...]): build the Maven project beside the calling CMakeLists.txt
# (its pom.xml and src/main) in the build directory, as part of `all`. OUTPUT is the file under
# Maven's target/ that the build makes; MAVEN_TARGET is set to that target/ folder.
# Used by armor_core and, through find_package(armor_core), by the core's plugins.
find_program(MAVEN_EXECUTABLE mvn)
if(NOT MAVEN_EXECUTABLE)
  message(FATAL_ERROR "${PROJECT_NAME} is built with Maven: 'mvn' not found (Debian: apt-get install maven openjdk-17-jdk-headless)")
endif()

function(maven_build output)
  set(_copy "${CMAKE_CURRENT_BINARY_DIR}/maven")
  file(GLOB_RECURSE _sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/src/main/*")
  # Maven's JVM with C1 alone and the serial GC, as the repository's .mvn/jvm.config has it (a
  # build is too short for the optimising JIT to pay back); the copy has no .mvn above it.
  file(WRITE "${_copy}/.mvn/jvm.config" "-XX:TieredStopAtLevel=1 -XX:+UseSerialGC\n")
  add_custom_command(
    OUTPUT "${_copy}/target/${output}"
    COMMAND "${CMAKE_COMMAND}" -E rm -rf "${_copy}/src" "${_copy}/target"
    COMMAND "${CMAKE_COMMAND}" -E copy_directory "${CMAKE_CURRENT_SOURCE_DIR}/src/main" "${_copy}/src/main"
    COMMAND "${CMAKE_COMMAND}" -E copy "${CMAKE_CURRENT_SOURCE_DIR}/pom.xml" "${_copy}/pom.xml"
    COMMAND "${MAVEN_EXECUTABLE}" -B -q -f "${_copy}/pom.xml" package -DskipTests ${ARGN}
    DEPENDS ${_sources} "${CMAKE_CURRENT_SOURCE_DIR}/pom.xml"
    COMMENT "Building ${PROJECT_NAME} with Maven"
    VERBATIM)
  add_custom_target(${PROJECT_NAME}_maven ALL DEPENDS "${_copy}/target/${output}")
  set(MAVEN_TARGET "${_copy}/target" PARENT_SCOPE)
endfunction()
