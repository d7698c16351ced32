# Precompiled Qt headers (DRIVEBENCH_PCH=ON), for builds without a compiler cache such as CI:
# parsing Qt's headers is most of a translation unit's compile time here (e.g. 2.4 of 3.2 CPU
# seconds for protocols/canopen/sdoclient.cpp, 6.4 s for <QtWidgets> alone).
#
# Four donor targets each build one header set once; every own target reuses the set that matches
# its Qt modules (chosen at the end of its folder, when its libraries are known). GCC takes a
# precompiled header only when the macros it depends on are defined the same way (QtTest's
# headers look at QT_WIDGETS_LIB, QT_GUI_LIB and QT_TESTCASE_BUILDDIR, QtCore's at
# QT_NO_URL_CAST_FROM_STRING); otherwise it reads the headers as text, so a target that matches
# no set still builds. QT_TESTCASE_BUILDDIR (only used by QFINDTESTDATA, which no test uses) is
# the build folder for every test, and QT_TESTCASE_SOURCEDIR (the target's own source folder,
# also only for QFINDTESTDATA) is left undefined, so that one set serves them all.
# Off by default: ccache does not cache compilations that use a precompiled header.

set(_drivebench_pch_core
    <QObject> <QString> <QByteArray> <QList> <QHash> <QMap> <QSet> <QVariant> <QStringList>
    <QTimer> <QPointer> <QCoreApplication> <QElapsedTimer> <QRegularExpression> <QFile> <QDir>
    <QFileInfo> <QDateTime> <QLoggingCategory> <QtEndian> <QMetaType> <QSaveFile> <QSettings>
    <QTextStream> <QJsonDocument> <QJsonObject> <QJsonArray>
    <algorithm> <chrono> <cstdint> <functional> <map> <memory> <optional> <utility> <vector>)
set(_drivebench_pch_widgets
    <QWidget> <QApplication> <QLabel> <QPushButton> <QToolButton> <QVBoxLayout> <QHBoxLayout>
    <QGridLayout> <QFormLayout> <QComboBox> <QLineEdit> <QSpinBox> <QDoubleSpinBox> <QCheckBox>
    <QTableView> <QTreeView> <QHeaderView> <QTabWidget> <QGroupBox> <QDockWidget> <QMainWindow>
    <QMenu> <QAction> <QMessageBox> <QFileDialog> <QDialog> <QDialogButtonBox>
    <QAbstractTableModel> <QStyledItemDelegate> <QPainter>)
set(_drivebench_pch_test <QtTest> <QSignalSpy> <QTemporaryDir> <QProcess> <QEventLoop>)

function(_drivebench_pch_donor name headers)
    set(source ${CMAKE_BINARY_DIR}/${name}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "// precompiled headers only\n")
    add_library(${name} STATIC ${source})
    target_link_libraries(${name} PRIVATE ${ARGN})
    # The same macros as every own target (drivebench_warnings) so that they can reuse it.
    target_compile_options(${name} PRIVATE -Wall -Wextra -Wpedantic)
    target_compile_definitions(${name} PRIVATE QT_NO_URL_CAST_FROM_STRING)
    target_precompile_headers(${name} PRIVATE ${headers})
    set_target_properties(${name} PROPERTIES QT_TESTCASE_BUILDDIR ${CMAKE_BINARY_DIR})
    if(name MATCHES "test$")
        _drivebench_pch_same_sourcedir(${name})
        _drivebench_pch_test_code(${name})
        _drivebench_test_code_sanitizers(${name})
    endif()
endfunction()

# Test code (the test programs and their support library) is compiled without optimisation when
# the header sets are used: about three quarters of the compile time of -O2 for a widget test,
# and test programs were 40 % of the build's processor time. The code under test keeps the
# build's level. GCC takes a set only at the level it was made at, so the test sets are made at
# -O0 too.
function(_drivebench_pch_test_code target)
    target_compile_options(${target} PRIVATE -O0)
endfunction()

# In a sanitizer build, test code keeps AddressSanitizer but not UBSan's checks: they made a test
# program's compilation take 1.3 to 1.7 times as long, and the code under test (every library)
# keeps them. Called for the test header sets too: GCC takes a set only with the same
# -fsanitize options.
function(_drivebench_test_code_sanitizers target)
    if(DRIVEBENCH_SANITIZE MATCHES "undefined")
        target_compile_options(${target} PRIVATE -fno-sanitize=undefined)
    endif()
endfunction()

# Command-line options come after the definitions, so -U removes Qt6::Test's per-folder value.
function(_drivebench_pch_same_sourcedir target)
    target_compile_options(${target} PRIVATE -UQT_TESTCASE_SOURCEDIR)
endfunction()

if(DRIVEBENCH_PCH)
    _drivebench_pch_donor(drivebench_pch_core "${_drivebench_pch_core}" Qt6::Core)
    _drivebench_pch_donor(drivebench_pch_widgets
        "${_drivebench_pch_core};${_drivebench_pch_widgets}" Qt6::Widgets)
    # Every test links Qt6::Network through its support library, and QtTest's headers look at
    # QT_NETWORK_LIB.
    _drivebench_pch_donor(drivebench_pch_test "${_drivebench_pch_core};${_drivebench_pch_test}"
        Qt6::Test Qt6::Network)
    _drivebench_pch_donor(drivebench_pch_widgettest
        "${_drivebench_pch_core};${_drivebench_pch_widgets};${_drivebench_pch_test}"
        Qt6::Test Qt6::Widgets Qt6::Network)
endif()

# Called for every own target (drivebench_warnings); picks the donor once the folder is read.
# Also decides what counts as test code (a target that links QtTest or the test support library)
# with or without the header sets.
function(drivebench_precompiled_headers target)
    # EVAL: a deferred call expands its arguments when it runs, not when it is queued.
    cmake_language(EVAL CODE "cmake_language(DEFER CALL _drivebench_pch_choose [[${target}]])")
endfunction()

function(_drivebench_pch_choose target)
    get_target_property(libs ${target} LINK_LIBRARIES)
    if(NOT libs)
        return() # plain C++ without Qt (bench/minimal)
    endif()
    set(kind core)
    if(libs MATCHES "Qt6::Widgets|drivebench_widgets|drivebench_gui|QCustomPlot")
        set(kind widgets)
    endif()
    if(libs MATCHES "Qt6::Test|drivebench_test_support")
        if(kind STREQUAL widgets)
            set(kind widgettest)
        else()
            set(kind test)
        endif()
        _drivebench_test_code_sanitizers(${target})
    endif()
    if(NOT DRIVEBENCH_PCH)
        return()
    endif()
    set_target_properties(${target} PROPERTIES PRECOMPILE_HEADERS_REUSE_FROM drivebench_pch_${kind}
                                               QT_TESTCASE_BUILDDIR ${CMAKE_BINARY_DIR})
    if(kind MATCHES "test$")
        _drivebench_pch_same_sourcedir(${target})
        _drivebench_pch_test_code(${target})
        # A test program includes its own moc output ("tst_x.moc"), so AUTOMOC's
        # mocs_compilation.cpp is empty unless the test has headers of its own: without the
        # header set it compiles in milliseconds instead of the 1.3 s that loading the set took
        # (for each of 150 tests, in both builds of the test command).
        get_target_property(type ${target} TYPE)
        get_target_property(sources ${target} SOURCES)
        if(type STREQUAL "EXECUTABLE" AND NOT sources MATCHES "\\.h(;|$)")
            get_target_property(dir ${target} BINARY_DIR)
            set_source_files_properties(${dir}/${target}_autogen/mocs_compilation.cpp
                                        PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
        endif()
    endif()
endfunction()
