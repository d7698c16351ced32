#include "logpanel.h"

#include "flowlayout.h"
#include "logconsole.h"
#include "widgetstyle.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace db::widgets {

LogPanel::LogPanel(LogConsole *console, QWidget *parent)
    : QWidget(parent)
    , m_console(console)
    , m_filter(new QComboBox(this))
    , m_status(new QLabel(this))
{
    m_filter->setObjectName(QStringLiteral("logFilter"));
    m_filter->setToolTip(tr("Which lines the log shows. Protocol traffic and debug lines are "
                            "kept only while they are shown."));
    for (auto f :
         { LogConsole::Filter::Events, LogConsole::Filter::Changes, LogConsole::Filter::Problems,
           LogConsole::Filter::WithTraffic, LogConsole::Filter::Everything })
        m_filter->addItem(LogConsole::filterName(f), QVariant::fromValue(int(f)));
    m_filter->setCurrentIndex(m_filter->findData(int(console->filter())));
    connect(m_filter, &QComboBox::currentIndexChanged, this,
            [this] { m_console->setFilter(LogConsole::Filter(m_filter->currentData().toInt())); });
    connect(console, &LogConsole::filterChanged, this, [this](LogConsole::Filter f) {
        m_filter->setCurrentIndex(m_filter->findData(int(f)));
    });

    auto *save = new QPushButton(tr("Save…"), this);
    save->setObjectName(QStringLiteral("saveLog"));
    save->setToolTip(tr("Save the lines shown to a text file"));
    connect(save, &QPushButton::clicked, this, &LogPanel::save);
    auto *clear = new QPushButton(tr("Clear"), this);
    connect(clear, &QPushButton::clicked, console, &LogConsole::clear);

    auto *row = new FlowLayout;
    row->addWidget(new QLabel(tr("Show:"), this));
    row->addWidget(m_filter);
    row->addWidget(save);
    row->addWidget(clear);
    row->addWidget(m_status);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(row);
    layout->addWidget(console, 1);
}

void LogPanel::save()
{
    QSettings settings;
    const QString folder =
        settings.value(QStringLiteral("log/folder"), QDir::homePath()).toString();
    const QString suggested = folder + QLatin1Char('/')
        + QStringLiteral("drivebench-%1.log")
              .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save log"), suggested,
                                                      tr("Log files (*.log *.txt)"));
    if (path.isEmpty())
        return;
    settings.setValue(QStringLiteral("log/folder"), QFileInfo(path).absolutePath());
    const QString problem = m_console->save(path);
    m_status->setText(problem.isEmpty() ? tr("Saved to %1").arg(QDir::toNativeSeparators(path))
                                        : problem);
    m_status->setStyleSheet(problem.isEmpty()
                                ? QString()
                                : QStringLiteral("color: %1").arg(style::errorColor().name()));
}

} // namespace db::widgets
