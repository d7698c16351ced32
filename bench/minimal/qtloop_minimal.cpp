// The smallest client we can write on Qt's event loop: the same exchange as refgo_minimal and
// sdo_minimal (one object read, wait for its answer, repeat), but waiting in QCoreApplication's
// loop, with the socket handled as TcpStream handles it (QTcpSocket connects, then a descriptor
// of its own is read and written directly, woken by a QSocketNotifier; TCP_NODELAY), and no
// protocol code. What it loses against the plain clients is the price of the event loop itself,
// the floor of any engine built on it; what the engine loses against it is the engine's own.
//   qtloop_minimal --uri refgo://HOST:PORT | canopen+slcan://HOST:PORT?node=N [--count N]
//                  [--object 6041:0]
#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTcpSocket>
#include <QTimer>
#include <QUrl>
#include <QUrlQuery>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <ctime>

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QString uriText, object = QStringLiteral("6041:0");
    long count = 20000;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == QLatin1String("--uri"))
            uriText = args[i + 1];
        else if (args[i] == QLatin1String("--count"))
            count = qMax(1L, args[i + 1].toLong());
        else if (args[i] == QLatin1String("--object"))
            object = args[i + 1];
    }
    const QUrl uri(uriText);
    const bool slcan = uri.scheme() == QLatin1String("canopen+slcan");
    const int node = QUrlQuery(uri).queryItemValue(QStringLiteral("node")).toInt();
    bool indexOk = false, subOk = false;
    const uint index = object.section(QLatin1Char(':'), 0, 0).toUInt(&indexOk, 16);
    const uint sub = object.section(QLatin1Char(':'), 1, 1).toUInt(&subOk, 16);
    if ((!slcan && uri.scheme() != QLatin1String("refgo")) || uri.host().isEmpty()
        || uri.port() <= 0 || (slcan && (node < 1 || node > 127)) || !indexOk || !subOk) {
        std::fprintf(stderr,
                     "qtloop_minimal: --uri refgo://HOST:PORT or canopen+slcan://HOST:PORT?node=N "
                     "and --object INDEX:SUB (hex) needed, not '%s' '%s'\n",
                     qPrintable(uriText), qPrintable(object));
        return 2;
    }

    // The request, and what marks the end of its answer: RefGo's prompt '>', or a line of the
    // node's SDO response (an abort, command 80, ends the run with an error).
    const QByteArray request = slcan
        ? QString::asprintf("t%03X840%02X%02X%02X00000000\r", 0x600 + node, index & 0xFF,
                            index >> 8, sub)
              .toLatin1()
        : QString::asprintf("OR%X,%X\r", index, sub).toLatin1();
    const QByteArray answer = QString::asprintf("t%03X8", 0x580 + node).toLatin1();

    QTcpSocket socket;
    socket.connectToHost(uri.host(), quint16(uri.port()),
                         QIODevice::ReadWrite | QIODevice::Unbuffered);
    if (!socket.waitForConnected(3000)) {
        std::fprintf(stderr, "qtloop_minimal: connect %s: %s\n", qPrintable(uriText),
                     qPrintable(socket.errorString()));
        return 1;
    }
    const int fd = ::fcntl(int(socket.socketDescriptor()), F_DUPFD_CLOEXEC, 0);
    if (fd < 0)
        return std::perror("qtloop_minimal: dup"), 1;
    socket.abort(); // the connection lives on in fd
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
    const auto send = [fd](const QByteArray &bytes) {
        return ::send(fd, bytes.constData(), size_t(bytes.size()), MSG_NOSIGNAL) == bytes.size();
    };
    if (slcan && !send("C\rS4\rO\r")) // close, 125 kbit/s, open; the acks are skipped below
        return std::fprintf(stderr, "qtloop_minimal: cannot send\n"), 1;
    QSocketNotifier readable(fd, QSocketNotifier::Read);

    char buffer[4096];
    QByteArray line, first; // first: RefGo's first answer, checked once (the object must exist)
    long done = 0;
    int result = 0;
    std::clock_t cpuStart = 0;
    std::chrono::steady_clock::time_point start;
    const auto finish = [&](int code) {
        result = code;
        app.quit();
    };
    QObject::connect(&readable, &QSocketNotifier::activated, [&] {
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n < 0 && (errno == EAGAIN || errno == EINTR))
            return;
        if (n <= 0)
            return finish((std::fprintf(stderr, "qtloop_minimal: connection closed\n"), 1));
        bool answered = false;
        for (ssize_t k = 0; k < n; ++k) {
            if (!slcan) {
                answered = answered || buffer[k] == '>';
                if (done == 0)
                    first += buffer[k];
                continue;
            }
            if (buffer[k] != '\r') {
                line += buffer[k];
                continue;
            }
            if (line.startsWith(answer)) {
                if (line.mid(5, 2) == "80")
                    return finish(
                        (std::fprintf(stderr, "qtloop_minimal: abort %s\n", line.constData()), 1));
                answered = true;
            }
            line.clear();
        }
        if (!answered)
            return;
        if (done == 0 && first.contains("ERROR"))
            return finish((std::fprintf(stderr, "qtloop_minimal: %s", first.constData()), 1));
        if (++done < count) {
            if (!send(request))
                return finish((std::fprintf(stderr, "qtloop_minimal: cannot send\n"), 1));
            return;
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double cpuUs = double(std::clock() - cpuStart) * 1e6 / CLOCKS_PER_SEC / double(count);
        std::printf("qt loop minimal: %ld round trips in %.3f s = %.0f/s, cpu %.1f us per round "
                    "trip\n",
                    count, seconds, double(count) / seconds, cpuUs);
        finish(0);
    });
    // A device that stops answering ends the run instead of hanging it.
    QTimer stall;
    long seen = -1;
    QObject::connect(&stall, &QTimer::timeout, [&] {
        if (seen == done)
            finish((std::fprintf(stderr, "qtloop_minimal: no answer within 1 s\n"), 1));
        seen = done;
    });
    stall.start(1000);

    cpuStart = std::clock();
    start = std::chrono::steady_clock::now();
    if (!send(request))
        return std::fprintf(stderr, "qtloop_minimal: cannot send\n"), 1;
    app.exec();
    ::close(fd);
    return result;
}
