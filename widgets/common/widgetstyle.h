#pragma once

#include "core/connectionhealth.h"
#include "core/deviceconnection.h"

#include <QColor>
#include <QFont>
#include <QIcon>

class QLabel;
class QWidget;

namespace db::widgets {

// Shared look of the drivebench widgets, so that values, states and errors read the same in
// every panel.
namespace style {

// Fixed-pitch font for values, addresses and hex, at the application's point size.
QFont monospaceFont();

// Colours of meaning (readable on light and dark palettes).
QColor okColor();
QColor warningColor();
QColor errorColor();
QColor inactiveColor();
// Behind a value that differs from its default (readable on light and dark palettes).
QColor changedBackground();

// A tooltip for plain text of any length (a description, an error): as rich text, which Qt
// wraps at a readable width, where a long plain-text tooltip is one line as wide as the screen.
// Empty stays empty.
QString toolTip(const QString &plainText);

// Greys a value label out (value not current) or restores its normal colour.
void setStale(QLabel *label, bool stale);
// Sets the text colour of a label (invalid colour = the palette's).
void setTextColor(QWidget *widget, const QColor &color);
// A text that changes often (a counter, a clock): the label gets a fixed size, so that a new
// text repaints the label alone instead of laying out the whole window. The width grows in steps
// of four average characters when the text needs more room and shrinks when it needs less than
// half of it.
void setFrequentText(QLabel *label, const QString &text);

// A round icon in the colour of a connection state.
QIcon connectionStateIcon(DeviceConnection::State state);
QColor connectionStateColor(DeviceConnection::State state);
// The colour and icon of what a connection's health says: green only while the device answers.
QColor healthColor(ConnectionHealth::Status status);
QIcon healthIcon(ConnectionHealth::Status status);

} // namespace style
} // namespace db::widgets
