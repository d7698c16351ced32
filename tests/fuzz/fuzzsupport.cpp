#include "fuzzsupport.h"

#include <QCoreApplication>

#include <cstdio>
#include <cstdlib>

namespace db::fuzz {

void ensureApplication()
{
    if (QCoreApplication::instance())
        return;
    static int argc = 1;
    static char name[] = "drivebench-fuzz";
    static char *argv[] = { name, nullptr };
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static QCoreApplication app(argc, argv);
}

void finding(const char *what)
{
    std::fprintf(stderr, "fuzz finding: %s\n", what);
    std::fflush(stderr);
    std::abort();
}

Input::Input(const uint8_t *data, size_t size)
    : m_data(reinterpret_cast<const char *>(data))
    , m_size(qsizetype(size))
{ }

quint8 Input::byte()
{
    return atEnd() ? 0 : quint8(m_data[m_pos++]);
}

quint16 Input::u16()
{
    const quint16 lo = byte();
    return quint16(lo | (quint16(byte()) << 8));
}

QByteArray Input::take(qsizetype n)
{
    n = qBound(qsizetype(0), n, remaining());
    QByteArray out(m_data + m_pos, n);
    m_pos += n;
    return out;
}

QByteArray Input::chunk(int max)
{
    const int n = max <= 0 ? 0 : byte() % (max + 1);
    return take(n);
}

QByteArray Input::rest()
{
    return take(remaining());
}

} // namespace db::fuzz
