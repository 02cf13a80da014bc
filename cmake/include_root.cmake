# The include root of sightline's library headers: every header of csp/, solvers/, domains/
# and experiments/ is included as "sightline/<folder>/...", the name it is installed under
# (include/sightline/<folder>/), so no header name can collide with a user's. In the build
# tree, <dir>/sightline/<folder> is a symbolic link to the source folder; the public API's
# own headers sit in include/sightline/ beside them.
function(sightline_make_include_root dir source_root)
  file(MAKE_DIRECTORY ${dir}/sightline)
  foreach(folder csp solvers domains experiments)
    if(NOT EXISTS ${dir}/sightline/${folder})
      file(CREATE_LINK ${source_root}/${folder} ${dir}/sightline/${folder} SYMBOLIC)
    endif()
  endforeach()
endfunction()
