#pragma once

#include <QPlainTextEdit>

namespace db::widgets {

// The application log: timestamped lines in level colours, bounded to maxLines() (older lines
// are dropped), with Clear and Copy all in the context menu. Appending is cheap and never
// blocks; lines may be fed from any thread through the Qt message handler (queued).
class LogConsole : public QPlainTextEdit
{
    Q_OBJECT
public:
    // Traffic: protocol lines (DeviceConnection::logLine), kept only while showTraffic() is on,
    // so that polling does not push the events out of the bounded log.
    enum class Level { Traffic, Info, Warning, Error };
    Q_ENUM(Level)

    static constexpr int kDefaultMaxLines = 5000;

    explicit LogConsole(QWidget *parent = nullptr);
    ~LogConsole() override;

    int maxLines() const;
    void setMaxLines(int lines);
    int lineCount() const;
    bool showTraffic() const { return m_showTraffic; }
    void setShowTraffic(bool show);

    // Routes qWarning()/qCritical()/qFatal() (and qInfo() of drivebench categories) to this
    // console as well as to the previous handler. One console at a time; the handler is removed
    // when the console is destroyed.
    void installMessageHandler();

public Q_SLOTS:
    void appendLine(db::widgets::LogConsole::Level level, const QString &text);
    void traffic(const QString &text) { appendLine(Level::Traffic, text); }
    void info(const QString &text) { appendLine(Level::Info, text); }
    void warning(const QString &text) { appendLine(Level::Warning, text); }
    void error(const QString &text) { appendLine(Level::Error, text); }
    void copyAll();

protected:
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    bool m_showTraffic = false;
};

} // namespace db::widgets
