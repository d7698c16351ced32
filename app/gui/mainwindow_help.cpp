// Help → User Manual (F1): the user manual in the program's language, rendered in a window of its
// own; Help → About.
#include "mainwindow.h"

#include "buildcommit.h"

#include "core/objectdef.h" // textLanguage()
#include "widgets/common/fittedimages.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
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

QString MainWindow::manualPath()
{
    // share/drivebench/manual beside bin/ (installed) or app/ (build tree), with the screenshots;
    // else the text built into the program. The language the program speaks, else English.
    const QString shared = QDir::cleanPath(QCoreApplication::applicationDirPath()
                                           + QStringLiteral("/../share/drivebench/manual"));
    for (const QString &language : { textLanguage(), QStringLiteral("en") }) {
        const QString name = QStringLiteral("manual.%1.md").arg(language);
        for (const QString &dir : { shared, QStringLiteral(":/manual") }) {
            if (QFileInfo::exists(dir + QLatin1Char('/') + name))
                return dir + QLatin1Char('/') + name;
        }
    }
    return {};
}

void MainWindow::showManual()
{
    if (!m_manual) {
        m_manual = new QDialog(this);
        m_manual->setObjectName(QStringLiteral("manual"));
        auto *browser = new QTextBrowser(m_manual);
        browser->setObjectName(QStringLiteral("manualText"));
        browser->setOpenExternalLinks(true);
        widgets::FittedImages::install(browser); // screenshots as wide as the window, no wider
        auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, m_manual);
        connect(buttons, &QDialogButtonBox::rejected, m_manual, &QDialog::close);
        auto *layout = new QVBoxLayout(m_manual);
        layout->addWidget(browser);
        layout->addWidget(buttons);
        m_manual->resize(900, 700);
    }
    // Loaded on every opening: the language may have changed in between.
    m_manual->setWindowTitle(tr("User Manual"));
    auto *browser = m_manual->findChild<QTextBrowser *>(QStringLiteral("manualText"));
    const QString path = manualPath();
    if (path.isEmpty()) {
        browser->setPlainText(tr("The manual is missing from this build."));
    } else {
        // As a source, so that the screenshots next to the file are found.
        const QUrl url = path.startsWith(QLatin1Char(':')) ? QUrl(QStringLiteral("qrc") + path)
                                                           : QUrl::fromLocalFile(path);
        if (browser->source() != url)
            browser->setSource(url, QTextDocument::MarkdownResource);
    }
    m_manual->show();
    m_manual->raise();
    m_manual->activateWindow();
}

} // namespace db::gui
