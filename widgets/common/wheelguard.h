#pragma once

#include <QObject>

namespace db::widgets {

// The mouse wheel changes a spin box or combo box only while it has the keyboard focus: turning
// the wheel to scroll a panel must never change a motion target or a parameter under the cursor.
// An unfocused box passes the wheel on to its parents (the panel scrolls instead).
//
// Installed once on the application (install()); it also gives the boxes Qt::StrongFocus as they
// are shown, so that the wheel alone does not focus them.
class WheelGuard : public QObject
{
public:
    explicit WheelGuard(QObject *parent = nullptr);
    // One guard for the whole application (idempotent); owned by qApp.
    static void install();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
};

} // namespace db::widgets
