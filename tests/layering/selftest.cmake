cmake_minimum_required(VERSION 3.25)
# The layer check must find every kind of violation in a tree made of them (bad/), so that a
# check that silently passes everything fails here.
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_CURRENT_LIST_DIR}/bad -P
                        ${CMAKE_CURRENT_LIST_DIR}/check_layers.cmake
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(text "${out}${err}")
if(rc EQUAL 0)
    message(FATAL_ERROR "the layer check accepted a tree full of violations:\n${text}")
endif()
foreach(expected
        "protocols/transport/tcpstream.cpp: transport must know no protocol"
        "protocols/refgo/refgoclient.cpp: protocol folders must not include each other"
        "protocols/refgo/refgoclient.cpp: includes an upper layer"
        "scope/recorder.cpp: includes an upper layer"
        "scope/recorder.cpp: morse/ and scope/ are independent"
        "scope/recorder.cpp: widget header below widgets/"
        "widgets/motion/jogpanel.cpp: client code includes the device side: #include \"canopen/device"
        "widgets/motion/jogpanel.cpp: client code includes the device side: #include \"simulation/"
        "widgets/motion/jogpanel.cpp: includes an upper layer"
        "devices/movingcap/movingcapdrive.cpp: includes an upper layer"
        "morse/decode/decoder.cpp: QCustomPlot below widgets/"
        "widgets/motion/jogpanel.cpp: cast to a concrete connection class: auto *refgo"
        "app/cli/commands_bad.cpp: cast to a concrete connection class: const auto *node")
    string(FIND "${text}" "${expected}" pos)
    if(pos EQUAL -1)
        message(FATAL_ERROR "the layer check missed: ${expected}\nits output:\n${text}")
    endif()
endforeach()
string(FIND "${text}" "auto *device = qobject_cast<db::DeviceConnection" pos)
if(NOT pos EQUAL -1)
    message(FATAL_ERROR "the layer check refused a cast to DeviceConnection:\n${text}")
endif()
message(STATUS "layer check self-test: every planted violation found")
