# Precompiled headers. Nearly every translation unit parses the same Qt and Eigen headers: with
# g++ 12 and C++20, <QDir> alone takes ~1.5 s to parse and a typical test spends half its compile
# time on headers. Precompiling them once per library, once for all core/CLI tests and once for
# all studio tests takes a clean build (CI's largest cost) down by a fifth.
# `-DLIPSYNC_PCH=OFF` builds without them (checks that every file includes what it uses).
option(LIPSYNC_PCH "Precompile the Qt, Eigen and standard headers most files include" ON)

set(LIPSYNC_PCH_CORE
  <QByteArray> <QDir> <QFile> <QFileInfo> <QJsonArray> <QJsonDocument> <QJsonObject> <QString>
  <QStringList> <QVector> <Eigen/Core>
  <algorithm> <cmath> <functional> <map> <memory> <optional> <string> <vector>)
set(LIPSYNC_PCH_GUI
  <QAction> <QApplication> <QComboBox> <QHBoxLayout> <QLabel> <QMessageBox> <QPainter>
  <QPushButton> <QUndoCommand> <QVBoxLayout> <QWidget>)

# lipsync_precompile(TARGET [GUI]): a PCH of its own for a target with many sources.
function(lipsync_precompile target)
  cmake_parse_arguments(ARG "GUI" "" "" ${ARGN})
  if(NOT LIPSYNC_PCH)
    return()
  endif()
  set(headers ${LIPSYNC_PCH_CORE})
  if(ARG_GUI)
    list(APPEND headers ${LIPSYNC_PCH_GUI})
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# lipsync_test_pch(NAME LIBS... [GUI]): a PCH built once in the holder library NAME, which the
# tests reuse (lipsync_reuse_pch). A reused PCH must have been built with a subset of each test's
# macro definitions (clang stops otherwise; g++ falls back to the plain headers): the holder
# lives in tests/, so Qt's QT_TESTCASE_BUILDDIR agrees, links only libraries every such test
# links, and has the definitions lipsync_add_qtest gives every test.
function(lipsync_test_pch name)
  cmake_parse_arguments(ARG "GUI" "" "LIBS" ${ARGN})
  if(NOT LIPSYNC_PCH)
    return()
  endif()
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp "// Holds the tests' precompiled header.\n")
  add_library(${name} STATIC ${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp)
  set_target_properties(${name} PROPERTIES AUTOMOC OFF)
  target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  target_compile_definitions(${name} PRIVATE ${LIPSYNC_TEST_DEFINITIONS})
  set(headers ${LIPSYNC_PCH_CORE} <QTest> <QSignalSpy> <QTemporaryDir>)
  if(ARG_GUI)
    list(APPEND headers ${LIPSYNC_PCH_GUI})
  endif()
  target_precompile_headers(${name} PRIVATE ${headers})
endfunction()

function(lipsync_reuse_pch target holder)
  if(TARGET ${holder})
    target_precompile_headers(${target} REUSE_FROM ${holder})
  endif()
endfunction()
