# Writes strahler(1) from the program's own help: `strahler --help` for the command list, then
# `strahler <command> --help` for each command it lists. Run by the build:
#   cmake -DPROGRAM=bin/strahler -DOUTPUT=strahler.1 -DVERSION=x.y.z -P make_manpage.cmake

function(help_of out)
  execute_process(COMMAND ${PROGRAM} ${ARGN} --help OUTPUT_VARIABLE text ERROR_VARIABLE text
                  RESULT_VARIABLE status TIMEOUT 30)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${ARGN} --help failed (${status}): ${text}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff treats a leading '.' or '\'' as a request and '\' as an escape.
function(roff_literal out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

help_of(main)
string(REGEX MATCH "commands:\n(.*)" listing "${main}")
string(REGEX MATCHALL "\n  [a-z][a-z-]* " names "\n${CMAKE_MATCH_1}")
string(TIMESTAMP today "%Y-%m-%d" UTC) # SOURCE_DATE_EPOCH when set, for reproducible builds
roff_literal(overview "${main}")
set(page ".TH STRAHLER 1 \"${today}\" \"strahler ${VERSION}\" \"User Commands\"
.SH NAME
strahler \\- river networks and terrain from a coastline, served as level-of-detail tiles
.SH SYNOPSIS
.B strahler
.I command
.RI [ options ]
.SH DESCRIPTION
strahler grows a hierarchical river network from a coastline (Genevaux et al., SIGGRAPH 2013),
builds the relief around it, caches the result as a compact world file and serves heightmap and
mesh tiles over HTTP.
.PP
.nf
${overview}.fi
.SH COMMANDS
")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  if(name STREQUAL "help" OR name STREQUAL "version")
    continue()
  endif()
  help_of(text ${name})
  roff_literal(text "${text}")
  string(APPEND page ".SS ${name}\n.nf\n${text}.fi\n")
endforeach()
string(APPEND page ".SH ENVIRONMENT
.TP
.B STRAHLER_CACHE_DIR
where generated worlds are cached (else $XDG_CACHE_HOME/strahler or ~/.cache/strahler)
.TP
.B STRAHLER_MODULE_DIR
the folder of the OpenImageIO module strahler_image_oiio.so (else beside the program or in
\\&../lib/strahler relative to it)
.SH EXIT STATUS
0 on success, 1 when the input or the work fails (with a message naming what and where), 2 for
a bad command line.
.SH SEE ALSO
README.md and docs/ in strahler's source (architecture, formats, HTTP endpoints, performance).
")
file(WRITE ${OUTPUT} "${page}")
