# The core's jar (its libraries are in lib/ beside it) and the Maven helper, for the plugins.
set(armor_core_JAR "${armor_core_DIR}/../java/armor-core.jar")
include("${armor_core_DIR}/maven_build.cmake")
