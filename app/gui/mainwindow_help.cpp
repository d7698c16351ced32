// Help → User Manual (F1): the README, built into the program, rendered in a window of its own;
// Help → About.
#include "mainwindow.h"

#include "buildcommit.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QMessageBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace db::gui {

QString MainWindow::aboutText() const
{
    return tr("<h3>drivebench %1</h3>"
              "<p>Commissioning tool for industrial drives.</p>"
              "<p>Built from commit %2 with Qt %3 (running on Qt %4) and QCustomPlot.</p>"
              "<p>Copyright 2026 The drivebench developers. drivebench has not been released "
              "under a public licence: all rights are reserved by its developers; ask them "
              "before you copy or redistribute it.</p>")
        .arg(QStringLiteral(DRIVEBENCH_VERSION), QStringLiteral(DRIVEBENCH_COMMIT),
             QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion()));
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About drivebench"), aboutText());
}

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
