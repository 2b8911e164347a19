# The layering check of core/ (docs/architecture.md).
#
# Every .h/.hpp/.cpp/.cc/.inl file under <root>/<folder>/ is scanned for #include lines:
#  - "X/..." where X is another folder of the tree must name a folder among <folder>'s declared
#    dependencies, or theirs (the transitive closure of what each folder's CMakeLists.txt passes
#    to sculpt_core_module());
#  - "X/..." where X is a folder outside core (render, app, sculpt, cli, haptics, tests, support,
#    bench) and "../..." paths are always errors;
#  - GL, GLFW, glad, GLEW, glm, Dear ImGui and hidapi headers are always errors: core has no GL,
#    no window and no device.
# Declared dependencies that form a cycle are errors too.
#
# Two ways in:
#  - include() it and call sculpt_check_layering(ROOT <dir> FOLDERS <f>... [BASE <dir>]) with a
#    variable SCULPT_LAYERING_DEPS_<f> per folder (what core/CMakeLists.txt does at configure
#    time; any violation is a FATAL_ERROR);
#  - cmake -DROOT=<dir> -DMANIFEST=<file> [-DBASE=<dir>] -P check_layering.cmake, where MANIFEST
#    sets SCULPT_LAYERING_FOLDERS and SCULPT_LAYERING_DEPS_<f> (the build writes one as
#    <build>/sculpt_layering.cmake; tests/data/layering/*/layers.cmake are small ones). Exits
#    non-zero, printing one "<file>:<line>: ..." per violation, when the tree breaks a rule.
#
# Paths in messages are relative to BASE (default: the parent of ROOT, so they read core/...).

cmake_minimum_required(VERSION 3.25)

set(SCULPT_LAYERING_OUTSIDE render app sculpt cli haptics tests support bench)
# Matched against the path inside <> or "" of an #include.
set(SCULPT_LAYERING_FORBIDDEN
  "^(GL|GLES[0-9]*|EGL|OpenGL|GLFW|glm|epoxy)/|^(glad|GLEW|glew|hidapi)|(^|/)imgui")

# The line numbers (1-based) of the lines of `file` that are exactly `text`, in `out_var`.
function(_sculpt_layering_line_numbers file text out_var)
  file(READ "${file}" _content)
  # One list element per line: protect the characters that CMake lists treat specially first.
  string(REPLACE "\\" "<bs>" _content "${_content}")
  string(REPLACE ";" "<sc>" _content "${_content}")
  string(REPLACE "[" "<lb>" _content "${_content}")
  string(REPLACE "]" "<rb>" _content "${_content}")
  string(REPLACE "\r" "" _content "${_content}")
  string(REPLACE "\n" ";" _content "${_content}")
  string(REPLACE "\\" "<bs>" text "${text}")
  string(REPLACE ";" "<sc>" text "${text}")
  string(REPLACE "[" "<lb>" text "${text}")
  string(REPLACE "]" "<rb>" text "${text}")
  string(REPLACE "\r" "" text "${text}")
  set(_numbers "")
  set(_n 0)
  foreach(_line IN LISTS _content)
    math(EXPR _n "${_n} + 1")
    if(_line STREQUAL text)
      list(APPEND _numbers ${_n})
    endif()
  endforeach()
  if(NOT _numbers)
    set(_numbers "?")
  endif()
  set(${out_var} "${_numbers}" PARENT_SCOPE)
endfunction()

# Every folder reachable from `folder` through SCULPT_LAYERING_DEPS_*, in `out_var`.
function(_sculpt_layering_closure folder out_var)
  set(_reached "")
  set(_todo ${SCULPT_LAYERING_DEPS_${folder}})
  while(_todo)
    list(POP_FRONT _todo _next)
    if(NOT _next IN_LIST _reached)
      list(APPEND _reached ${_next})
      list(APPEND _todo ${SCULPT_LAYERING_DEPS_${_next}})
    endif()
  endwhile()
  list(SORT _reached)
  set(${out_var} "${_reached}" PARENT_SCOPE)
endfunction()

# Scans the tree; returns the violations (one message per element) in `out_var`.
function(sculpt_layering_violations out_var)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "ROOT;BASE" "FOLDERS")
  if(NOT ARG_BASE)
    get_filename_component(ARG_BASE "${ARG_ROOT}" DIRECTORY)
  endif()
  set(_errors "")
  foreach(_folder IN LISTS ARG_FOLDERS)
    if(NOT IS_DIRECTORY "${ARG_ROOT}/${_folder}")
      list(APPEND _errors "${_folder}: declared as a folder but ${ARG_ROOT}/${_folder} does not exist")
    endif()
    foreach(_dep IN LISTS SCULPT_LAYERING_DEPS_${_folder})
      if(NOT _dep IN_LIST ARG_FOLDERS)
        list(APPEND _errors "${_folder}: declared dependency '${_dep}' is not a folder of the tree")
      endif()
    endforeach()
    _sculpt_layering_closure(${_folder} _allowed_${_folder})
    if(_folder IN_LIST _allowed_${_folder})
      list(APPEND _errors "${_folder}: the declared dependencies form a cycle through ${_folder}")
    endif()
  endforeach()

  foreach(_folder IN LISTS ARG_FOLDERS)
    set(_allowed ${_allowed_${_folder}})
    string(REPLACE ";" " " _allowed_text "${_allowed}")
    if(_allowed_text STREQUAL "")
      set(_allowed_text "no other folder")
    endif()
    file(GLOB_RECURSE _files LIST_DIRECTORIES false
      "${ARG_ROOT}/${_folder}/*.h" "${ARG_ROOT}/${_folder}/*.hpp" "${ARG_ROOT}/${_folder}/*.cpp"
      "${ARG_ROOT}/${_folder}/*.cc" "${ARG_ROOT}/${_folder}/*.inl")
    list(SORT _files)
    foreach(_file IN LISTS _files)
      file(STRINGS "${_file}" _includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
      file(RELATIVE_PATH _shown "${ARG_BASE}" "${_file}")
      foreach(_line IN LISTS _includes)
        if(NOT _line MATCHES "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]*)[>\"]")
          continue()
        endif()
        set(_quote "${CMAKE_MATCH_1}")
        set(_path "${CMAKE_MATCH_2}")
        set(_problem "")
        if(_path MATCHES "${SCULPT_LAYERING_FORBIDDEN}")
          set(_problem "core may not include GL, GLFW, glad, glm, ImGui or hidapi headers (they belong to render/, app/sculpt/ or haptics/)")
        elseif(_quote STREQUAL "\"" AND _path MATCHES "^\\.\\./")
          set(_problem "include core headers as \"<folder>/<file>\", not by a relative path")
        elseif(_quote STREQUAL "\"" AND _path MATCHES "^([^/]+)/")
          set(_target "${CMAKE_MATCH_1}")
          if(_target STREQUAL _folder)
            # Its own folder.
          elseif(_target IN_LIST ARG_FOLDERS)
            if(NOT _target IN_LIST _allowed)
              set(_problem "folder ${_folder} may not include folder ${_target} (${_folder} may use: ${_allowed_text} - declare it in ${_folder}/CMakeLists.txt if it belongs below ${_folder}, else move the code)")
            endif()
          elseif(_target IN_LIST SCULPT_LAYERING_OUTSIDE)
            set(_problem "core may not include ${_target}/ (outside core)")
          endif()
        endif()
        if(_problem)
          _sculpt_layering_line_numbers("${_file}" "${_line}" _numbers)
          foreach(_number IN LISTS _numbers)
            string(STRIP "${_line}" _stripped)
            list(APPEND _errors "${_shown}:${_number}: ${_stripped}: ${_problem}")
          endforeach()
        endif()
      endforeach()
    endforeach()
  endforeach()
  set(${out_var} "${_errors}" PARENT_SCOPE)
endfunction()

# Fails (FATAL_ERROR) with every violation, one per line.
function(sculpt_check_layering)
  sculpt_layering_violations(_errors ${ARGN})
  if(_errors)
    list(LENGTH _errors _count)
    list(JOIN _errors "\n  " _text)
    message(FATAL_ERROR "Layering check failed (${_count} problem(s), see docs/architecture.md):\n  ${_text}\n")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(NOT ROOT OR NOT MANIFEST)
    message(FATAL_ERROR "usage: cmake -DROOT=<core dir> -DMANIFEST=<layers file> [-DBASE=<dir>] -P check_layering.cmake")
  endif()
  include("${MANIFEST}")
  if(NOT SCULPT_LAYERING_FOLDERS)
    message(FATAL_ERROR "${MANIFEST} sets no SCULPT_LAYERING_FOLDERS")
  endif()
  set(_base_args "")
  if(BASE)
    set(_base_args BASE "${BASE}")
  endif()
  sculpt_check_layering(ROOT "${ROOT}" FOLDERS ${SCULPT_LAYERING_FOLDERS} ${_base_args})
  list(LENGTH SCULPT_LAYERING_FOLDERS _count)
  message(STATUS "Layering check passed (${_count} folders under ${ROOT})")
endif()
