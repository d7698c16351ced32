// The install layout: `cmake --install` into a temporary DESTDIR yields the programs, desktop
// entry, icons, AppStream metadata, man pages made from --help and the bash completion, and the
// installed files pass Debian's own validators (each check is skipped where its tool is absent).
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kAppId = QStringLiteral("org.drivebench.drivebench");
const QStringList kPrograms = { QStringLiteral("drivebench"), QStringLiteral("drivebench-cli"),
                                QStringLiteral("drivebench-sim") };

struct Run
{
    int exitCode = -1; // -2: no exit within the time limit (killed), -3: crashed or not started
    QString out;
    QString err;
};

Run run(const QString &program, const QStringList &args,
        const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
{
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForStarted(10000))
        return { -3, {}, QStringLiteral("%1: cannot start: %2").arg(program, p.errorString()) };
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return { -2, {}, QStringLiteral("%1: no exit within 60 s").arg(program) };
    }
    return { p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -3,
             QString::fromUtf8(p.readAllStandardOutput()),
             QString::fromUtf8(p.readAllStandardError()) };
}

} // namespace

class TestPackaging : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void installsTheExpectedFiles_data();
    void installsTheExpectedFiles();
    void desktopEntryStartsAnInstalledProgram();
    void desktopEntryIsValid();
    void metainfoIsValid();
    void manPagesAreMadeFromHelp_data();
    void manPagesAreMadeFromHelp();
    void bashCompletion_data();
    void bashCompletion();
    void germanManualIsComplete();

private:
    QString installed(const QString &relative) const { return m_root.filePath(relative); }
    QString manPage(const QString &program) const;

    QTemporaryDir m_destdir;
    QDir m_root; // DESTDIR + prefix (/usr)
};

void TestPackaging::initTestCase()
{
    QVERIFY(m_destdir.isValid());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("DESTDIR"), m_destdir.path());
    const Run install = run(QStringLiteral(DRIVEBENCH_CMAKE),
                            { QStringLiteral("--install"), QStringLiteral(DRIVEBENCH_BINARY_DIR),
                              QStringLiteral("--prefix"), QStringLiteral("/usr") },
                            env);
    QVERIFY2(install.exitCode == 0, qPrintable(install.out + install.err));
    m_root = QDir(m_destdir.filePath(QStringLiteral("usr")));
}

void TestPackaging::installsTheExpectedFiles_data()
{
    QTest::addColumn<QString>("path");
    for (const QString &program : kPrograms)
        QTest::newRow(qPrintable(program)) << QStringLiteral("bin/") + program;
    QTest::newRow("desktop") << QStringLiteral("share/applications/%1.desktop").arg(kAppId);
    QTest::newRow("metainfo") << QStringLiteral("share/metainfo/%1.metainfo.xml").arg(kAppId);
    QTest::newRow("svg") << QStringLiteral("share/icons/hicolor/scalable/apps/%1.svg").arg(kAppId);
#ifdef DRIVEBENCH_PNG_ICONS
    for (int size : { 16, 22, 24, 32, 48, 64, 128, 256 })
        QTest::newRow(qPrintable(QStringLiteral("png %1").arg(size)))
            << QStringLiteral("share/icons/hicolor/%1x%1/apps/%2.png").arg(size).arg(kAppId);
#endif
#ifdef DRIVEBENCH_MAN_PAGES
    for (const QString &program : kPrograms)
        QTest::newRow(qPrintable(program + QStringLiteral(".1")))
            << QStringLiteral("share/man/man1/%1.1.gz").arg(program);
#endif
    QTest::newRow("completion") << QStringLiteral(
        "share/bash-completion/completions/drivebench-cli");
    QTest::newRow("copyright") << QStringLiteral("share/doc/drivebench/copyright");
    QTest::newRow("manual en") << QStringLiteral("share/drivebench/manual/manual.en.md");
    QTest::newRow("manual de") << QStringLiteral("share/drivebench/manual/manual.de.md");
    QTest::newRow("manual screenshot")
        << QStringLiteral("share/drivebench/manual/docs/screenshot-main.png");
}

// The installed German manual is the English one translated: the same sections, the same
// screenshots and the same commands; every screenshot either shows is installed beside it.
void TestPackaging::germanManualIsComplete()
{
    struct Outline
    {
        QStringList levels; // "##", "###" per heading, in order
        QStringList images;
        QStringList commands; // indented lines, up to a comment
    };
    const auto outline = [this](const QString &name) {
        Outline o;
        QFile file(installed(QStringLiteral("share/drivebench/manual/") + name));
        if (!file.open(QIODevice::ReadOnly))
            return o;
        static const QRegularExpression image(QStringLiteral(R"(!\[[^\]]*\]\(([^)]+)\))"));
        for (const QString &line : QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'))) {
            if (line.startsWith(QLatin1Char('#')))
                o.levels.append(line.section(QLatin1Char(' '), 0, 0));
            for (auto it = image.globalMatch(line); it.hasNext();)
                o.images.append(it.next().captured(1));
            if (line.startsWith(QLatin1String("    ")) && !line.trimmed().isEmpty())
                o.commands.append(line.section(QLatin1String("  #"), 0, 0).trimmed());
        }
        return o;
    };
    const Outline en = outline(QStringLiteral("manual.en.md"));
    const Outline de = outline(QStringLiteral("manual.de.md"));
    QVERIFY(en.levels.size() > 10);
    QCOMPARE(de.levels, en.levels);
    QCOMPARE(de.images, en.images);
    QCOMPARE(de.commands.size(), en.commands.size());
    for (const QString &image : en.images)
        QVERIFY2(QFileInfo::exists(installed(QStringLiteral("share/drivebench/manual/") + image)),
                 qPrintable(image));
}

void TestPackaging::installsTheExpectedFiles()
{
    QFETCH(QString, path);
    const QFileInfo file(installed(path));
    QVERIFY2(file.isFile(), qPrintable(path + QStringLiteral(" is not installed")));
    QVERIFY2(file.size() > 0, qPrintable(path + QStringLiteral(" is empty")));
    if (path.startsWith(QStringLiteral("bin/")))
        QVERIFY2(file.isExecutable(), qPrintable(path + QStringLiteral(" is not executable")));
#ifdef DRIVEBENCH_PNG_ICONS
    if (path.startsWith(QStringLiteral("share/icons/")) && path.endsWith(QStringLiteral(".png"))) {
        const QString size = path.section(QLatin1Char('/'), 3, 3); // "48x48"
        QFile png(file.filePath());
        QVERIFY(png.open(QIODevice::ReadOnly));
        const QByteArray header = png.read(24); // signature, IHDR length and type, width, height
        QCOMPARE(header.left(8), QByteArray("\x89PNG\r\n\x1a\n"));
        const auto be32 = [&](int at) {
            return QStringLiteral("%1").arg(
                (quint8(header[at]) << 24) | (quint8(header[at + 1]) << 16)
                | (quint8(header[at + 2]) << 8) | quint8(header[at + 3]));
        };
        QCOMPARE(be32(16) + QLatin1Char('x') + be32(20), size);
    }
#endif
}

void TestPackaging::desktopEntryStartsAnInstalledProgram()
{
    QFile desktop(installed(QStringLiteral("share/applications/%1.desktop").arg(kAppId)));
    QVERIFY(desktop.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(desktop.readAll());
    const auto value = [&](const QString &key) {
        return QRegularExpression(QStringLiteral("^%1=(.*)$").arg(key),
                                  QRegularExpression::MultilineOption)
            .match(text)
            .captured(1);
    };
    QCOMPARE(value(QStringLiteral("Exec")), QStringLiteral("drivebench"));
    QVERIFY(QFileInfo(installed(QStringLiteral("bin/drivebench"))).isExecutable());
    QCOMPARE(value(QStringLiteral("Icon")), kAppId);
}

void TestPackaging::desktopEntryIsValid()
{
    const QString validator =
        QStandardPaths::findExecutable(QStringLiteral("desktop-file-validate"));
    if (validator.isEmpty())
        QSKIP("desktop-file-validate not installed (desktop-file-utils)");
    const Run check =
        run(validator, { installed(QStringLiteral("share/applications/%1.desktop").arg(kAppId)) });
    QCOMPARE(check.exitCode, 0);
    QVERIFY2(check.out.isEmpty() && check.err.isEmpty(), qPrintable(check.out + check.err));
}

void TestPackaging::metainfoIsValid()
{
    const QString appstreamcli = QStandardPaths::findExecutable(QStringLiteral("appstreamcli"));
    if (appstreamcli.isEmpty())
        QSKIP("appstreamcli not installed (appstream)");
    const Run check =
        run(appstreamcli,
            { QStringLiteral("validate"), QStringLiteral("--no-net"), QStringLiteral("--pedantic"),
              QStringLiteral("--no-color"),
              installed(QStringLiteral("share/metainfo/%1.metainfo.xml").arg(kAppId)) });
    QVERIFY2(check.exitCode == 0, qPrintable(check.out + check.err));
}

QString TestPackaging::manPage(const QString &program) const
{
    const Run unzip = run(QStringLiteral("gzip"),
                          { QStringLiteral("-dc"),
                            installed(QStringLiteral("share/man/man1/%1.1.gz").arg(program)) });
    return unzip.exitCode == 0 ? unzip.out : QString();
}

void TestPackaging::manPagesAreMadeFromHelp_data()
{
    QTest::addColumn<QString>("program");
    for (const QString &program : kPrograms)
        QTest::newRow(qPrintable(program)) << program;
}

void TestPackaging::manPagesAreMadeFromHelp()
{
#ifndef DRIVEBENCH_MAN_PAGES
    QSKIP("built without man pages (python3 not found)");
#endif
    QFETCH(QString, program);
    const QString page = manPage(program);
    QVERIFY2(page.startsWith(QStringLiteral(".TH %1 1 ").arg(program.toUpper())),
             qPrintable(page.left(200)));

    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    const Run help =
        run(installed(QStringLiteral("bin/") + program), { QStringLiteral("--help") }, env);
    QCOMPARE(help.exitCode, 0);
    // Every option and command of --help is on the page (troff writes '-' as "\-").
    static const QRegularExpression entry(QStringLiteral("^  (-\\S+|[a-z][a-z-]+)"),
                                          QRegularExpression::MultilineOption);
    int entries = 0;
    for (const auto &match : entry.globalMatch(help.out)) {
        QString word = match.captured(1);
        word.remove(QLatin1Char(','));
        QVERIFY2(page.contains(QStringLiteral("\\fB")
                               + word.replace(QLatin1Char('-'), QStringLiteral("\\-"))),
                 qPrintable(program + QStringLiteral(": no entry for ") + match.captured(1)));
        ++entries;
    }
    QVERIFY(entries >= 4);

    const QString man = QStandardPaths::findExecutable(QStringLiteral("man"));
    if (man.isEmpty())
        QSKIP("man not installed: the page was not rendered");
    QProcessEnvironment manEnv = QProcessEnvironment::systemEnvironment();
    manEnv.insert(QStringLiteral("MANWIDTH"), QStringLiteral("80"));
    const Run render = run(man,
                           { QStringLiteral("--warnings"), QStringLiteral("-E"),
                             QStringLiteral("UTF-8"), QStringLiteral("-l"),
                             installed(QStringLiteral("share/man/man1/%1.1.gz").arg(program)) },
                           manEnv);
    QCOMPARE(render.exitCode, 0);
    QVERIFY2(render.err.isEmpty(), qPrintable(render.err)); // troff warnings
    QVERIFY(render.out.contains(QStringLiteral("OPTIONS")));
}

void TestPackaging::bashCompletion_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QStringList>("expected");
    QTest::addColumn<QStringList>("absent");
    QTest::newRow("commands") << QStringLiteral("drivebench-cli re")
                              << QStringList { "read", "refgo", "restore", "reset", "record" }
                              << QStringList { "write", "--hex" };
    QTest::newRow("schemes") << QStringLiteral("drivebench-cli read ")
                             << QStringList { "refgo://", "canopen+slcan://",
                                              "canopen+virtualcan://" }
                             << QStringList { "read" };
    QTest::newRow("nmt states after an option with a value")
        << QStringLiteral("drivebench-cli --timeout 500 nmt canopen+slcan://h?node=1 st")
        << QStringList { "start", "stop" } << QStringList { "preop", "--all" };
    QTest::newRow("lss services") << QStringLiteral("drivebench-cli lss canopen+slcan://h s")
                                  << QStringList { "switch-global", "switch-selective", "set-node",
                                                   "set-bitrate", "store" }
                                  << QStringList { "inquire" };
    QTest::newRow("options") << QStringLiteral("drivebench-cli read refgo://h 6041:0 --h")
                             << QStringList { "--hex", "--help", "--help-all" }
                             << QStringList { "--timeout" };
    QTest::newRow("option value") << QStringLiteral("drivebench-cli --timeout ") << QStringList {}
                                  << QStringList { "read" };
}

void TestPackaging::bashCompletion()
{
    QFETCH(QString, line);
    QFETCH(QStringList, expected);
    QFETCH(QStringList, absent);
    const QString bash = QStandardPaths::findExecutable(QStringLiteral("bash"));
    const QString framework = QStringLiteral("/usr/share/bash-completion/bash_completion");
    if (bash.isEmpty() || !QFileInfo::exists(framework))
        QSKIP("bash or bash-completion not installed");

    // Completes `line` as bash would after TAB, with the installed program first on PATH. Like
    // readline, the words are also split at ':' and '=' (COMP_WORDBREAKS): a URI is many words.
    const QString script = QStringLiteral(
        "source \"$1\" && source \"$2\" || exit 9\n"
        "COMP_LINE=$3; COMP_POINT=${#COMP_LINE}\n"
        "read -ra COMP_WORDS <<<\"$(sed -E 's/([:=]+)/ \\1 /g' <<<\"$COMP_LINE\")\"\n"
        "[[ $COMP_LINE == *' ' ]] && COMP_WORDS+=('')\n"
        "COMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n"
        "_drivebench_cli drivebench-cli \"${COMP_WORDS[COMP_CWORD]}\" "
        "\"${COMP_WORDS[COMP_CWORD - 1]}\"\n"
        "printf '%s\\n' \"${COMPREPLY[@]}\"\n");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("PATH"),
               installed(QStringLiteral("bin")) + QLatin1Char(':')
                   + env.value(QStringLiteral("PATH")));
    const Run completion =
        run(bash,
            { QStringLiteral("-c"), script, QStringLiteral("bash"), framework,
              installed(QStringLiteral("share/bash-completion/completions/drivebench-cli")), line },
            env);
    QVERIFY2(completion.exitCode == 0, qPrintable(completion.err));
    const QStringList offered = completion.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString &word : expected)
        QVERIFY2(
            offered.contains(word),
            qPrintable(word + QStringLiteral(" not offered: ") + offered.join(QLatin1Char(' '))));
    for (const QString &word : absent)
        QVERIFY2(!offered.contains(word), qPrintable(word + QStringLiteral(" offered")));
}

QTEST_GUILESS_MAIN(TestPackaging)
#include "tst_packaging.moc"
