#include "logconsole.h"
#include "core/filewriter.h"

#include "widgetstyle.h"

#include "core/printable.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QDateTime>
#include <QFileInfo>
#include <QMenu>
#include <QPointer>
#include <QSaveFile>
#include <QScrollBar>
#include <QTextBlock>

namespace db::widgets {

namespace {

QPointer<LogConsole> g_console;
QtMessageHandler g_previousHandler = nullptr;

void messageHandler(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    if (g_previousHandler)
        g_previousHandler(type, context, message);
    if (!g_console)
        return;
    LogConsole::Level level = LogConsole::Level::Info;
    switch (type) {
    case QtDebugMsg:
        // Only our own categories: Qt's internals would drown the log.
        if (!context.category || !QByteArray(context.category).startsWith("drivebench"))
            return;
        level = LogConsole::Level::Debug;
        break;
    case QtInfoMsg:
        level = LogConsole::Level::Info;
        break;
    case QtWarningMsg:
        level = LogConsole::Level::Warning;
        break;
    case QtCriticalMsg:
    case QtFatalMsg:
        level = LogConsole::Level::Error;
        break;
    }
    QString text = message;
    if (context.category && qstrcmp(context.category, "default") != 0)
        text = QStringLiteral("[%1] %2").arg(QLatin1String(context.category), message);
    // Queued: the message may come from any thread, and from inside a paint or layout.
    QMetaObject::invokeMethod(
        g_console.data(),
        [console = g_console, level, text] {
            if (console)
                console->appendLine(level, text);
        },
        Qt::QueuedConnection);
}

} // namespace

LogConsole::LogConsole(QWidget *parent)
    : QPlainTextEdit(parent)
{
    setReadOnly(true);
    setUndoRedoEnabled(false);
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setMaximumBlockCount(kDefaultMaxLines);
    setFont(style::monospaceFont());
    setPlaceholderText(tr("Connection events and warnings appear here."));
}

LogConsole::~LogConsole()
{
    if (g_console == this) {
        qInstallMessageHandler(g_previousHandler);
        g_previousHandler = nullptr;
        g_console = nullptr;
    }
}

int LogConsole::maxLines() const
{
    return m_maxLines;
}

void LogConsole::setMaxLines(int lines)
{
    m_maxLines = qMax(1, lines);
    while (int(m_lines.size()) > m_maxLines)
        m_lines.pop_front();
    setMaximumBlockCount(m_maxLines);
}

int LogConsole::lineCount() const
{
    return document()->isEmpty() ? 0 : document()->blockCount();
}

void LogConsole::installMessageHandler()
{
    if (!g_console)
        g_previousHandler = qInstallMessageHandler(messageHandler);
    g_console = this;
}

bool LogConsole::showTraffic() const
{
    return m_filter == Filter::WithTraffic || m_filter == Filter::Everything;
}

void LogConsole::setShowTraffic(bool show)
{
    if (show != showTraffic())
        setFilter(show ? Filter::WithTraffic : Filter::Events);
}

void LogConsole::setFilter(Filter filter)
{
    if (filter == m_filter)
        return;
    m_filter = filter;
    // Lines no filter shows any more are gone for good: traffic and debug are kept only while
    // shown.
    std::erase_if(m_lines, [this](const Line &line) { return !keeps(line.level); });
    rerender();
    Q_EMIT filterChanged(filter);
}

QString LogConsole::filterName(Filter filter)
{
    switch (filter) {
    case Filter::Events:
        return tr("Changes and events");
    case Filter::Changes:
        return tr("Changes only");
    case Filter::Problems:
        return tr("Warnings and errors");
    case Filter::WithTraffic:
        return tr("Events and protocol traffic");
    case Filter::Everything:
        return tr("Everything, with debug lines");
    }
    return {};
}

bool LogConsole::keeps(Level level) const
{
    switch (level) {
    case Level::Traffic:
        return showTraffic();
    case Level::Debug:
        return m_filter == Filter::Everything;
    default:
        return true;
    }
}

bool LogConsole::shows(Level level) const
{
    switch (m_filter) {
    case Filter::Changes:
        return level == Level::Change;
    case Filter::Problems:
        return level == Level::Warning || level == Level::Error;
    case Filter::Events:
        return level != Level::Traffic && level != Level::Debug;
    case Filter::WithTraffic:
        return level != Level::Debug;
    case Filter::Everything:
        return true;
    }
    return true;
}

void LogConsole::appendLine(Level level, const QString &text)
{
    if (!keeps(level))
        return;
    // One entry, one line: lines quote device answers and file contents, whose control
    // characters (and U+2029, a paragraph break to QTextDocument) are shown as escapes.
    m_lines.push_back(Line { QDateTime::currentDateTime(), level, printable(text) });
    if (int(m_lines.size()) > m_maxLines)
        m_lines.pop_front();
    if (!shows(level))
        return;
    QScrollBar *bar = verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    render(m_lines.back());
    if (atEnd)
        bar->setValue(bar->maximum());
}

void LogConsole::render(const Line &line)
{
    QTextCharFormat format;
    switch (line.level) {
    case Level::Traffic:
    case Level::Debug:
        format.setForeground(style::inactiveColor());
        break;
    case Level::Info:
        break;
    case Level::Change:
        format.setFontWeight(QFont::Bold);
        break;
    case Level::Warning:
        format.setForeground(style::warningColor());
        break;
    case Level::Error:
        format.setForeground(style::errorColor());
        break;
    }
    QTextCharFormat timeFormat;
    timeFormat.setForeground(style::inactiveColor());

    QTextCursor cursor(document());
    cursor.movePosition(QTextCursor::End);
    if (!document()->isEmpty())
        cursor.insertBlock();
    cursor.insertText(line.time.toString(QStringLiteral("HH:mm:ss.zzz ")), timeFormat);
    cursor.insertText(line.text, format);
}

void LogConsole::rerender()
{
    QPlainTextEdit::clear();
    for (const Line &line : m_lines) {
        if (shows(line.level))
            render(line);
    }
    QScrollBar *bar = verticalScrollBar();
    bar->setValue(bar->maximum());
}

QString LogConsole::shownText() const
{
    static const char *const names[] = { "TRAFFIC", "INFO", "WARNING", "ERROR", "CHANGE", "DEBUG" };
    QString out;
    for (const Line &line : m_lines) {
        if (!shows(line.level))
            continue;
        out += line.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz "))
            + QLatin1String(names[int(line.level)]) + QLatin1Char(' ') + line.text
            + QLatin1Char('\n');
    }
    return out;
}

QString LogConsole::save(const QString &path) const
{
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    const QByteArray bytes = shownText().toUtf8();
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text) || file.write(bytes) != bytes.size()
        || !file.commit())
        return tr("cannot write %1: %2").arg(QFileInfo(path).fileName(), file.errorString());
    return {};
}

void LogConsole::copyAll()
{
    QApplication::clipboard()->setText(toPlainText());
}

void LogConsole::clear()
{
    m_lines.clear();
    QPlainTextEdit::clear();
}

void LogConsole::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu *menu = createStandardContextMenu(event->pos());
    menu->addSeparator();
    menu->addAction(tr("Copy All"), this, &LogConsole::copyAll);
    menu->addAction(tr("Clear"), this, &LogConsole::clear);
    QMenu *show = menu->addMenu(tr("Show"));
    for (Filter f : { Filter::Events, Filter::Changes, Filter::Problems, Filter::WithTraffic,
                      Filter::Everything }) {
        QAction *a = show->addAction(filterName(f), this, [this, f] { setFilter(f); });
        a->setCheckable(true);
        a->setChecked(f == m_filter);
    }
    menu->exec(event->globalPos());
    delete menu;
}

} // namespace db::widgets
