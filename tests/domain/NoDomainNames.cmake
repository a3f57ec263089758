# cmake -DSOURCE=<repo> -DALLOWLIST=<file> -P NoDomainNames.cmake
#
# Nothing in stdlib/ or runtime/ may name a predicate, type or kernel of a shipped domain
# (domains/*.ksm, examples/**/*.ksm): kits receive them as indices and data from the
# generated binding (docs/binding.md). Collects those names from the .ksm files, then scans
# every C/C++ string literal under stdlib/ and runtime/ for one that equals a name exactly.
# An allowlist entry `NAME PATH -- REASON` (PATH relative to the repository, or `*`) permits
# one; every entry must give its reason.

cmake_minimum_required(VERSION 3.20)

# ---- names of the shipped domains -------------------------------------------------------
file(GLOB ksm_files ${SOURCE}/domains/*.ksm)
file(GLOB_RECURSE example_ksm ${SOURCE}/examples/*.ksm)
list(APPEND ksm_files ${example_ksm})
if(NOT ksm_files)
  message(FATAL_ERROR "no shipped domain file under ${SOURCE}/domains or ${SOURCE}/examples")
endif()
set(id "[A-Za-z_][A-Za-z0-9_]*")
set(ws "[ \t\r\n]")
set(names "")
foreach(f ${ksm_files})
  file(READ ${f} text)
  string(REGEX REPLACE "//[^\n]*" "" text "${text}")
  string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" text "${text}")
  # `evidence P(t, ...), Q(t);` / `query R(t);`
  string(REGEX MATCHALL "(evidence|query)${ws}+[^;]*;" decls "${text}")
  foreach(d ${decls})
    string(REGEX REPLACE "^(evidence|query)" "" d "${d}")
    string(REGEX MATCHALL "${id}${ws}*\\(" preds "${d}")
    foreach(p ${preds})
      string(REGEX REPLACE "${ws}*\\($" "" p "${p}")
      list(APPEND names ${p})
    endforeach()
  endforeach()
  # `type T;` / `type T = {...};`
  string(REGEX MATCHALL "(^|[;}\n])${ws}*type${ws}+${id}" types "${text}")
  foreach(t ${types})
    string(REGEX REPLACE ".*type${ws}+" "" t "${t}")
    list(APPEND names ${t})
  endforeach()
  # `kernel pair A / B = ...;`, `kernel K(o: T) reverse R = ...;`
  string(REGEX MATCHALL "kernel${ws}[^=;]*" kernels "${text}")
  foreach(k ${kernels})
    string(REGEX REPLACE "\\([^)]*\\)" "" k "${k}")
    string(REGEX REPLACE "^kernel${ws}+(pair${ws}+)?" "" k "${k}")
    string(REGEX MATCHALL "${id}" ks "${k}")
    list(REMOVE_ITEM ks reverse)
    list(APPEND names ${ks})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES names)
list(LENGTH names count)
if(count EQUAL 0)
  message(FATAL_ERROR "no predicate, type or kernel found in ${ksm_files}")
endif()

# ---- the allowlist ------------------------------------------------------------------------
set(allowed "")
if(EXISTS ${ALLOWLIST})
  file(STRINGS ${ALLOWLIST} entries)
  foreach(e ${entries})
    if(e MATCHES "^[ \t]*(#|$)")
      continue()
    endif()
    if(NOT e MATCHES "^(${id})[ \t]+([^ \t]+)[ \t]+--[ \t]+[^ \t].*$")
      message(FATAL_ERROR "${ALLOWLIST}: '${e}': expected `NAME PATH -- REASON`")
    endif()
    list(APPEND allowed "${CMAKE_MATCH_1}@${CMAKE_MATCH_2}")
  endforeach()
endif()

# ---- string literals under stdlib/ and runtime/ --------------------------------------------
file(GLOB_RECURSE sources ${SOURCE}/stdlib/*.h ${SOURCE}/stdlib/*.hpp ${SOURCE}/stdlib/*.cpp ${SOURCE}/stdlib/*.cc
                          ${SOURCE}/runtime/*.h ${SOURCE}/runtime/*.hpp ${SOURCE}/runtime/*.cpp ${SOURCE}/runtime/*.cc)
set(found "")
foreach(src ${sources})
  file(RELATIVE_PATH rel ${SOURCE} ${src})
  file(STRINGS ${src} lines)
  set(line_no 0)
  foreach(line IN LISTS lines)
    math(EXPR line_no "${line_no} + 1")
    if(NOT line MATCHES "\"" OR line MATCHES "^[ \t]*(//|\\*|/\\*)")
      continue()
    endif()
    string(REGEX REPLACE "\\\\\\\\" "" line "${line}")  # escaped backslashes
    string(REGEX REPLACE "\\\\\"" "" line "${line}")   # escaped quotes
    string(REGEX REPLACE "'\"'" "" line "${line}")      # the character '"'
    # The literals before a `//` comment (a comment's quotes are not literals).
    set(literals "")
    while(TRUE)
      string(FIND "${line}" "\"" q)
      string(FIND "${line}" "//" c)
      if(q EQUAL -1 OR (NOT c EQUAL -1 AND c LESS q))
        break()
      endif()
      math(EXPR start "${q} + 1")
      string(SUBSTRING "${line}" ${start} -1 line)
      string(FIND "${line}" "\"" e)
      if(e EQUAL -1)
        break()
      endif()
      string(SUBSTRING "${line}" 0 ${e} word)
      list(APPEND literals "${word}")
      math(EXPR start "${e} + 1")
      string(SUBSTRING "${line}" ${start} -1 line)
    endwhile()
    foreach(word IN LISTS literals)
      if(word IN_LIST names)
        if("${word}@${rel}" IN_LIST allowed OR "${word}@*" IN_LIST allowed)
          continue()
        endif()
        list(APPEND found "${rel}:${line_no}: \"${word}\"")
      endif()
    endforeach()
  endforeach()
endforeach()

if(found)
  list(JOIN found "\n  " report)
  message(FATAL_ERROR "stdlib/ or runtime/ names a predicate, type or kernel of a shipped domain "
                      "(take it from the generated binding, or allowlist it with a reason in ${ALLOWLIST}):\n  ${report}")
endif()
message(STATUS "${count} names of shipped domains; none in the string literals of stdlib/ and runtime/")
