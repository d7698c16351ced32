// MainWindow: the object-dictionary editor and parameter-set pages and the
// "Parameters" menu. Only composition; the widgets do the work.

#include "mainwindow.h"

#include "widgets/common/logconsole.h"
#include "widgets/odeditor/odeditor.h"
#include "widgets/parameters/paramcompareview.h"
#include "widgets/parameters/parametersetactions.h"
#include "widgets/scope/scopepage.h"

#include <QMenuBar>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>

namespace db::gui {

namespace {
constexpr int kMessageMs = 10000; // status bar messages of parameter commands
}

void MainWindow::createParameterPages()
{
    m_odEditor = new widgets::OdEditor(m_pages);
    m_compareView = new widgets::ParamCompareView(m_pages);
    m_paramActions = new widgets::ParameterSetActions(this, this);
    m_pages->addTab(m_odEditor, tr("Object Dictionary"));
    m_pages->addTab(m_compareView, tr("Parameter Sets"));
    m_odEditor->addToolActions(tr("Parameter set"),
                               { m_paramActions->backUpAction(), m_paramActions->compareAction(),
                                 m_paramActions->storeAction() });

    QMenu *menu = new QMenu(tr("&Parameters"), this);
    menu->addAction(m_paramActions->backUpAction());
    menu->addAction(m_paramActions->compareAction());
    menu->addSeparator();
    menu->addAction(m_paramActions->storeAction());
    m_paramActions->storeAction()->setShortcut(QKeySequence::Save); // asks before it stores
    menu->addAction(m_paramActions->factoryDefaultsAction());
    menu->addSeparator();
    menu->addAction(m_paramActions->exportDcfAction());
    // Before Help, which is the last menu.
    const QList<QAction *> menus = menuBar()->actions();
    menuBar()->insertMenu(menus.isEmpty() ? nullptr : menus.last(), menu);

    connect(m_paramActions, &widgets::ParameterSetActions::compareRequested, this, [this] {
        m_pages->setCurrentWidget(m_compareView);
        m_compareView->chooseFile();
    });
    connect(m_paramActions, &widgets::ParameterSetActions::message, this,
            [this](const QString &text, bool ok) {
                statusBar()->showMessage(text, kMessageMs);
                if (ok)
                    m_log->info(text);
                else
                    m_log->error(text);
            });
    connect(m_paramActions, &widgets::ParameterSetActions::storedPermanently, this,
            [this](DeviceConnection *connection) {
                m_unstored.remove(connection);
                updateWindowTitle();
            });
    connect(m_compareView, &widgets::ParamCompareView::restoreFinished, this,
            [this](const RestoreReport &report) {
                const QString text = report.summary();
                if (report.succeeded())
                    m_log->info(text);
                else
                    m_log->error(text);
            });
}

// Standard keys: Ctrl+O connect (File menu), Ctrl+S store permanently (asks first), F5 re-read
// the objects (on the Scope page: start or stop the recording), Ctrl+F filter them.
void MainWindow::createShortcuts(QMenu *view)
{
    QAction *refresh = view->addAction(tr("&Refresh Objects"), this, [this] {
        if (m_central->currentWidget() == m_pages && m_pages->currentWidget() == m_scopePage) {
            toggleScope();
            return;
        }
        m_pages->setCurrentWidget(m_odEditor);
        m_odEditor->readAll();
    });
    refresh->setObjectName(QStringLiteral("refreshAction"));
    refresh->setShortcut(QKeySequence::Refresh);
    QAction *filter = view->addAction(tr("&Filter Objects"), this, [this] {
        m_pages->setCurrentWidget(m_odEditor);
        m_odEditor->focusFilter();
    });
    filter->setObjectName(QStringLiteral("filterAction"));
    filter->setShortcut(QKeySequence::Find);
}

void MainWindow::attachParameters(DeviceConnection *connection)
{
    m_odEditor->setConnection(connection);
    m_compareView->setConnection(connection);
    m_paramActions->setConnection(connection);
}

} // namespace db::gui
