# Writes the man page collide.1 and collide.1.gz with help2man (Debian's help2man), from the
# --help texts: `collide --help` and `--version` make its NAME, SYNOPSIS, DESCRIPTION and
# OPTIONS; each subcommand's `collide SUBCOMMAND --help` becomes a part of a SUBCOMMANDS
# section, as printed; packaging/collide.h2m adds ENVIRONMENT, FILES, EXAMPLES and SEE ALSO.
# The build runs it (packaging/CMakeLists.txt):
#   cmake -DCOLLIDE=bin -DHELP2MAN=prog -DGZIP=prog -DINCLUDE=collide.h2m -DOUT=dir/collide.1 -P manpage.cmake

function(run out)
  execute_process(COMMAND ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "manpage.cmake: '${command}' failed (${code}): ${err}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Text as roff in a no-fill block: backslashes as \e, hyphens as \- (minus signs, which copy as
# the '-' of an option), and a line starting with '.' or ''' kept from being read as a request.
function(roff_verbatim out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} ".nf\n${text}.fi\n" PARENT_SCOPE)
endfunction()

run(top "${COLLIDE}" --help)
# The subcommands: the lines of the "Subcommands:" list, "  NAME   description".
string(REGEX REPLACE ".*\nSubcommands:\n" "" list "${top}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z-]*" names "${list}")
set(section "[SUBCOMMANDS]\nEach subcommand has its own options; `collide SUBCOMMAND \\-\\-help` prints them.\n")
set(count 0)
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  run(help "${COLLIDE}" "${name}" --help)
  roff_verbatim(body "${help}")
  string(APPEND section ".SS \"collide ${name}\"\n${body}")
  math(EXPR count "${count} + 1")
endforeach()
if(count LESS 2)
  message(FATAL_ERROR "manpage.cmake: no subcommands found in `collide --help`:\n${top}")
endif()

file(READ "${INCLUDE}" static)
get_filename_component(dir "${OUT}" DIRECTORY)
file(WRITE "${dir}/collide.h2m" "${static}\n${section}")
run(ignored "${HELP2MAN}" --no-info --no-discard-stderr --section=1
    "--name=an educational rigid-body collision simulator (1D, 2D, 3D)"
    "--include=${dir}/collide.h2m" "--output=${OUT}" "${COLLIDE}")
run(ignored "${GZIP}" -9 -n -f -k "${OUT}")
