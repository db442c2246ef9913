# collide_installed_headers(TARGET): TARGET's headers are included as "engine/...",
# "render/...": from the source tree when building, from include/collide when installed
# (find_package(Collide), packaging/).
function(collide_installed_headers target)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/collide>)
endfunction()
