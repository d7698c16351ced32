#include "logconsole.h"

#include "widgetstyle.h"

#include "core/printable.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QDateTime>
#include <QMenu>
#include <QPointer>
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
        return;
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
    return maximumBlockCount();
}

void LogConsole::setMaxLines(int lines)
{
    setMaximumBlockCount(qMax(1, lines));
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

void LogConsole::setShowTraffic(bool show)
{
    m_showTraffic = show;
}

void LogConsole::appendLine(Level level, const QString &text)
{
    if (level == Level::Traffic && !m_showTraffic)
        return;
    QTextCharFormat format;
    switch (level) {
    case Level::Traffic:
        format.setForeground(style::inactiveColor());
        break;
    case Level::Info:
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

    QScrollBar *bar = verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();

    QTextCursor cursor(document());
    cursor.movePosition(QTextCursor::End);
    if (!document()->isEmpty())
        cursor.insertBlock();
    cursor.insertText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz ")), timeFormat);
    // One entry, one line: lines quote device answers and file contents, whose control
    // characters (and U+2029, a paragraph break to QTextDocument) are shown as escapes.
    cursor.insertText(printable(text), format);

    if (atEnd)
        bar->setValue(bar->maximum());
}

void LogConsole::copyAll()
{
    QApplication::clipboard()->setText(toPlainText());
}

void LogConsole::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu *menu = createStandardContextMenu(event->pos());
    menu->addSeparator();
    menu->addAction(tr("Copy All"), this, &LogConsole::copyAll);
    menu->addAction(tr("Clear"), this, &LogConsole::clear);
    QAction *traffic =
        menu->addAction(tr("Show Protocol Traffic"), this, &LogConsole::setShowTraffic);
    traffic->setCheckable(true);
    traffic->setChecked(m_showTraffic);
    menu->exec(event->globalPos());
    delete menu;
}

} // namespace db::widgets
