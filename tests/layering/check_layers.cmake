cmake_minimum_required(VERSION 3.25)
# Fails when an #include breaks the layer picture of ARCHITECTURE.md:
#  - nothing below widgets/ (protocols/, scope/) uses Qt Widgets or QCustomPlot;
#  - protocols/transport knows no protocol;
#  - protocol folders include each other only through core, transport, canopen, cia402 (the
#    drive profile every drive family shares) and simulation;
#  - protocols/ and scope/ never include widgets/ or app/.
# Run: cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
set(violations "")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/protocols/*.h ${SOURCE_DIR}/protocols/*.cpp
     ${SOURCE_DIR}/scope/*.h ${SOURCE_DIR}/scope/*.cpp)
set(shared_protocol_folders core transport canopen cia402 simulation)
foreach(src IN LISTS sources)
    file(STRINGS ${SOURCE_DIR}/${src} includes REGEX "^[ \t]*#[ \t]*include")
    string(REGEX MATCH "^protocols/([a-z0-9]+)/" _ ${src})
    set(folder ${CMAKE_MATCH_1})
    foreach(line IN LISTS includes)
        if(line MATCHES "[<\"](QtWidgets|QWidget|QMainWindow|QDialog|QAbstractButton|QApplication|qcustomplot\\.h)")
            list(APPEND violations "${src}: widget header below widgets/: ${line}")
        endif()
        if(line MATCHES "[<\"](widgets|app)/")
            list(APPEND violations "${src}: includes an upper layer: ${line}")
        endif()
        if(folder AND line MATCHES "\"([a-z0-9]+)/[a-z0-9_]+\\.h\"")
            set(target ${CMAKE_MATCH_1})
            if(NOT target STREQUAL folder)
                if(folder STREQUAL "transport" AND NOT target STREQUAL "core")
                    list(APPEND violations "${src}: transport must know no protocol: ${line}")
                elseif(NOT target IN_LIST shared_protocol_folders)
                    list(APPEND violations "${src}: protocol folders must not include each other: ${line}")
                endif()
            endif()
        endif()
    endforeach()
endforeach()
if(violations)
    list(JOIN violations "\n" text)
    message(FATAL_ERROR "layering violations:\n${text}")
endif()
list(LENGTH sources n)
message(STATUS "layering: ${n} files checked, no violations")
