# Each of FILES (separated by '|') holds, in its first 2 KB (a VTK XML
# file's header), the matching text of TEXTS.
#   cmake -DFILES=a.vtp|b.vtp -DTEXTS=x|y -P CheckFileHeads.cmake
string(REPLACE "|" ";" files "${FILES}")
string(REPLACE "|" ";" texts "${TEXTS}")
foreach(file text IN ZIP_LISTS files texts)
  file(READ "${file}" head LIMIT 2048)
  string(FIND "${head}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${file}: its header lacks ${text}:\n${head}")
  endif()
endforeach()
