#pragma once

#include <QWidget>

class QComboBox;
class QLabel;

namespace db::widgets {

class LogConsole;

// The Log dock: which lines to show (changes, events, problems, traffic, debug), Save… and
// Clear above the console.
class LogPanel : public QWidget
{
    Q_OBJECT
public:
    explicit LogPanel(LogConsole *console, QWidget *parent = nullptr);

    LogConsole *console() const { return m_console; }
    QComboBox *filterBox() const { return m_filter; }

private:
    void save();

    LogConsole *m_console;
    QComboBox *m_filter;
    QLabel *m_status;
};

} // namespace db::widgets
