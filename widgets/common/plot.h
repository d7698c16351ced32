#pragma once
// QCustomPlot, for every source that draws with it. Its header includes the whole QtPrintSupport
// module, and with it every header of QtCore, QtGui and QtWidgets: about 6 of the 10 to 13
// seconds a scope source took to compile. The header itself needs none of that (it includes the
// Qt classes it names), so the module's umbrella is skipped through its include guard; a source
// that uses a printing class includes that class's own header. A Qt version whose umbrella has
// another guard reads the umbrella as before: slower, not wrong.
#ifndef QT_QTPRINTSUPPORT_MODULE_H
#define QT_QTPRINTSUPPORT_MODULE_H
#include <qcustomplot.h>
#undef QT_QTPRINTSUPPORT_MODULE_H
#else
#include <qcustomplot.h>
#endif
