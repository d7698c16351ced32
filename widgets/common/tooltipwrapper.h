#pragma once

#include <QObject>

namespace db::widgets {

// Long plain-text tooltips wrap: Qt shows a plain-text tooltip as one line, as wide as its text
// (a long description runs off the screen), and wraps only rich text. A widget's plain tooltip
// longer than kWrapAfter characters is shown as rich text (style::toolTip()) instead; short ones
// and rich text are left to Qt. Item views' tooltips come from their models, which use
// style::toolTip() for descriptions themselves.
//
// Installed once on the application (install()).
class ToolTipWrapper : public QObject
{
public:
    static constexpr int kWrapAfter = 80;

    explicit ToolTipWrapper(QObject *parent = nullptr);
    // One wrapper for the whole application (idempotent); owned by qApp.
    static void install();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
};

} // namespace db::widgets
