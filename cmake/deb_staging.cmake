# CPACK_PRE_BUILD_SCRIPTS of the Debian package (CMakeLists.txt), run in the package's staging tree
# before dpkg-shlibdeps computes its Depends:
#  * the Python module: `cmake --install` puts it in <prefix>/lib/python3.X/dist-packages, where
#    Debian's Python finds it under /usr/local; under /usr it looks in /usr/lib/python3/dist-packages,
#    so the package holds it there (as deep below lib/: the module's run path to Simbody holds);
#  * the bundled Release Simbody: its libraries are this package's own, so debian/shlibs.local
#    names them with no dependency (else dpkg-shlibdeps would take Debian's libsimbody3.7, which
#    has the same SONAMEs, for them). CPack leaves debian/ out of the package.
set(root "${CPACK_TEMPORARY_DIRECTORY}${CPACK_PACKAGING_INSTALL_PREFIX}")
if(CPACK_PACKAGING_INSTALL_PREFIX STREQUAL "/usr")
  file(GLOB sites LIST_DIRECTORIES true "${root}/lib/python3.*/dist-packages")
  foreach(site IN LISTS sites)
    file(MAKE_DIRECTORY "${root}/lib/python3/dist-packages")
    file(GLOB entries LIST_DIRECTORIES true "${site}/*")
    foreach(e IN LISTS entries)
      get_filename_component(n "${e}" NAME)
      file(RENAME "${e}" "${root}/lib/python3/dist-packages/${n}")
    endforeach()
    get_filename_component(version_dir "${site}" DIRECTORY)
    file(REMOVE_RECURSE "${version_dir}")
  endforeach()
endif()
file(GLOB bundled "${root}/lib/dtwin/simbody/lib/lib*.so.*")
set(shlibs "")
foreach(lib IN LISTS bundled)
  get_filename_component(n "${lib}" NAME)
  if(n MATCHES "^(lib[^.]+)\\.so\\.(.+)$")
    string(APPEND shlibs "${CMAKE_MATCH_1} ${CMAKE_MATCH_2}\n")
  endif()
endforeach()
if(shlibs)
  file(WRITE "${CPACK_TEMPORARY_DIRECTORY}/debian/shlibs.local" "${shlibs}")
endif()
