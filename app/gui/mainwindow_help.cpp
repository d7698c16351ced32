// Help → User Manual (F1): the README, built into the program, rendered in a window of its own.
#include "mainwindow.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace db::gui {

void MainWindow::showManual()
{
    if (!m_manual) {
        m_manual = new QDialog(this);
        m_manual->setObjectName(QStringLiteral("manual"));
        m_manual->setWindowTitle(tr("User Manual"));
        auto *browser = new QTextBrowser(m_manual);
        browser->setObjectName(QStringLiteral("manualText"));
        browser->setOpenExternalLinks(true);
        QFile readme(QStringLiteral(":/manual/README.md"));
        if (readme.open(QIODevice::ReadOnly))
            browser->setMarkdown(QString::fromUtf8(readme.readAll()));
        else
            browser->setPlainText(tr("The manual is missing from this build."));
        auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, m_manual);
        connect(buttons, &QDialogButtonBox::rejected, m_manual, &QDialog::close);
        auto *layout = new QVBoxLayout(m_manual);
        layout->addWidget(browser);
        layout->addWidget(buttons);
        m_manual->resize(900, 700);
    }
    m_manual->show();
    m_manual->raise();
    m_manual->activateWindow();
}

} // namespace db::gui
