#pragma once

#include <QDateTime>
#include <QPlainTextEdit>

#include <deque>

namespace db::widgets {

// The application log: timestamped lines in level colours, bounded to maxLines() (older lines
// are dropped), with a filter by kind, Save, Clear and Copy all. Appending is cheap and never
// blocks; lines may be fed from any thread through the Qt message handler (queued).
//
// Kinds of line: what the user changed on a device (Change), connection events (Info), warnings
// and errors, protocol traffic (DeviceConnection::logLine) and internal debug lines. Traffic and
// debug lines are kept only while they are shown, so that polling does not push the events out
// of the bounded log.
class LogConsole : public QPlainTextEdit
{
    Q_OBJECT
public:
    enum class Level { Traffic, Info, Warning, Error, Change, Debug };
    Q_ENUM(Level)

    // Which lines are shown.
    enum class Filter {
        Events, // changes, events, warnings and errors
        Changes, // what the user changed only
        Problems, // warnings and errors
        WithTraffic, // events plus protocol traffic
        Everything, // events, traffic and internal debug lines
    };
    Q_ENUM(Filter)

    static constexpr int kDefaultMaxLines = 5000;

    explicit LogConsole(QWidget *parent = nullptr);
    ~LogConsole() override;

    int maxLines() const;
    void setMaxLines(int lines);
    // Lines shown now.
    int lineCount() const;
    bool showTraffic() const;
    // On: Filter::WithTraffic; off: back to Filter::Events.
    void setShowTraffic(bool show);
    Filter filter() const { return m_filter; }
    void setFilter(Filter filter);
    static QString filterName(Filter filter); // translated

    // The lines shown now as "yyyy-MM-dd HH:mm:ss.zzz LEVEL text", one per line.
    QString shownText() const;
    // Writes shownText() to `path` atomically; an empty string on success, else the cause.
    QString save(const QString &path) const;

    // Routes qWarning()/qCritical()/qFatal() (and qInfo()/qDebug() of drivebench categories) to
    // this console as well as to the previous handler. One console at a time; the handler is
    // removed when the console is destroyed.
    void installMessageHandler();

public Q_SLOTS:
    void appendLine(db::widgets::LogConsole::Level level, const QString &text);
    void traffic(const QString &text) { appendLine(Level::Traffic, text); }
    void info(const QString &text) { appendLine(Level::Info, text); }
    void warning(const QString &text) { appendLine(Level::Warning, text); }
    void error(const QString &text) { appendLine(Level::Error, text); }
    void change(const QString &text) { appendLine(Level::Change, text); }
    void debug(const QString &text) { appendLine(Level::Debug, text); }
    void copyAll();
    // Forgets every line, shown or not.
    void clear();

Q_SIGNALS:
    void filterChanged(db::widgets::LogConsole::Filter filter);

protected:
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    struct Line
    {
        QDateTime time;
        Level level;
        QString text;
    };
    bool shows(Level level) const;
    // Kept at all (traffic and debug only while shown).
    bool keeps(Level level) const;
    void render(const Line &line);
    void rerender();

    std::deque<Line> m_lines;
    int m_maxLines = kDefaultMaxLines;
    Filter m_filter = Filter::Events;
};

} // namespace db::widgets
