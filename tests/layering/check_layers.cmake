cmake_minimum_required(VERSION 3.25)
# Fails when an #include breaks the layer picture of ARCHITECTURE.md:
#  - layers, bottom up: protocols/ < devices/ < morse/, scope/ < widgets/ < app/; a file never
#    includes a header of a higher layer, and morse/ and scope/ do not include each other;
#  - nothing below widgets/ uses Qt Widgets or QCustomPlot;
#  - protocols/transport knows no protocol;
#  - protocol folders include each other only through core, description, parameters, transport,
#    canopen, cia402 (the drive profile every drive family shares) and simulation;
#  - client code never includes the device side: outside device/ folders, simulation/, devices/,
#    app/ and tests, no file includes a header from a device/ folder or from simulation/.
#  - widgets/, app/gui/ and app/cli/ work through DeviceConnection and its interfaces: no cast
#    to a concrete connection class (qobject_cast, dynamic_cast or static_cast to a *Connection
#    other than DeviceConnection).
# Run: cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
set(violations "")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/protocols/*.h ${SOURCE_DIR}/protocols/*.cpp
     ${SOURCE_DIR}/devices/*.h ${SOURCE_DIR}/devices/*.cpp
     ${SOURCE_DIR}/morse/*.h ${SOURCE_DIR}/morse/*.cpp
     ${SOURCE_DIR}/scope/*.h ${SOURCE_DIR}/scope/*.cpp
     ${SOURCE_DIR}/widgets/*.h ${SOURCE_DIR}/widgets/*.cpp)
set(protocol_folders core description parameters transport canopen refgo vabus cia402 motion
    simulation)
set(shared_protocol_folders core description parameters transport canopen cia402 simulation)
# Rank of a layer; morse and scope share one.
set(rank_protocols 0)
set(rank_devices 1)
set(rank_morse 2)
set(rank_scope 2)
set(rank_widgets 3)
set(rank_app 4)
foreach(src IN LISTS sources)
    file(STRINGS ${SOURCE_DIR}/${src} includes REGEX "^[ \t]*#[ \t]*include")
    string(REGEX MATCH "^([a-z]+)/" _ ${src})
    set(layer ${CMAKE_MATCH_1})
    set(folder "")
    if(src MATCHES "^protocols/([a-z0-9]+)/")
        set(folder ${CMAKE_MATCH_1})
    endif()
    set(device_side FALSE)
    if(src MATCHES "/device/" OR folder STREQUAL "simulation" OR layer STREQUAL "devices")
        set(device_side TRUE)
    endif()
    foreach(line IN LISTS includes)
        if(NOT line MATCHES "\"([^\"]+)\"")
            if(NOT layer STREQUAL "widgets" AND line MATCHES "<(QtWidgets|QWidget|QMainWindow|QDialog|QAbstractButton|QApplication)")
                list(APPEND violations "${src}: widget header below widgets/: ${line}")
            endif()
            continue()
        endif()
        set(path ${CMAKE_MATCH_1})
        if(NOT layer STREQUAL "widgets" AND path MATCHES "qcustomplot\\.h")
            list(APPEND violations "${src}: QCustomPlot below widgets/: ${line}")
        endif()
        # Layer of the included header (flat includes stay in the including folder).
        set(target_layer "")
        set(target_folder "")
        if(path MATCHES "^([a-z0-9]+)/")
            set(head ${CMAKE_MATCH_1})
            if(head IN_LIST protocol_folders)
                set(target_layer protocols)
                set(target_folder ${head})
            elseif(head MATCHES "^(devices|morse|scope|widgets|app)$")
                set(target_layer ${head})
            endif()
        endif()
        if(target_layer)
            if(${rank_${target_layer}} GREATER ${rank_${layer}})
                list(APPEND violations "${src}: includes an upper layer: ${line}")
            elseif(${rank_${target_layer}} EQUAL ${rank_${layer}}
                   AND NOT target_layer STREQUAL layer)
                list(APPEND violations "${src}: morse/ and scope/ are independent: ${line}")
            endif()
        endif()
        if(folder AND target_folder AND NOT target_folder STREQUAL folder)
            if(folder STREQUAL "transport" AND NOT target_folder STREQUAL "core")
                list(APPEND violations "${src}: transport must know no protocol: ${line}")
            elseif(NOT target_folder IN_LIST shared_protocol_folders)
                list(APPEND violations "${src}: protocol folders must not include each other: ${line}")
            endif()
        endif()
        if(NOT device_side AND (path MATCHES "/device/" OR path MATCHES "^simulation/"
                                OR path MATCHES "^devices/[a-z0-9]+/.*(sim|server|simulated)"))
            list(APPEND violations "${src}: client code includes the device side: ${line}")
        endif()
    endforeach()
endforeach()
# Casts to concrete connection classes above the protocols.
file(GLOB_RECURSE cast_sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/widgets/*.h ${SOURCE_DIR}/widgets/*.cpp
     ${SOURCE_DIR}/app/gui/*.h ${SOURCE_DIR}/app/gui/*.cpp
     ${SOURCE_DIR}/app/cli/*.h ${SOURCE_DIR}/app/cli/*.cpp)
foreach(src IN LISTS cast_sources)
    file(STRINGS ${SOURCE_DIR}/${src} casts
         REGEX "(qobject_cast|dynamic_cast|static_cast)<[^>]*Connection[ \t]*\\*")
    foreach(line IN LISTS casts)
        string(REGEX MATCH "_cast<[ \t]*(const[ \t]+)?([A-Za-z0-9_:]*Connection)[ \t]*\\*" _
               "${line}")
        set(class "${CMAKE_MATCH_2}") # MATCHES below overwrites CMAKE_MATCH_n
        if(class AND NOT class MATCHES "(^|:)DeviceConnection$")
            string(REPLACE ";" "" line "${line}") # a list separator to CMake
            string(STRIP "${line}" line)
            list(APPEND violations "${src}: cast to a concrete connection class: ${line}")
        endif()
    endforeach()
endforeach()
list(LENGTH cast_sources n_cast)

if(violations)
    foreach(v IN LISTS violations)
        message(STATUS "violation: ${v}")
    endforeach()
    list(LENGTH violations count)
    message(FATAL_ERROR "${count} layering violations (listed above)")
endif()
list(LENGTH sources n)
message(STATUS "layering: ${n} files checked (${n_cast} for connection casts), no violations")
