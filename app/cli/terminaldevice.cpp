#include "terminaldevice.h"

#include "core/printable.h"

namespace db::cli {

TerminalDevice::TerminalDevice(FILE *stream)
{
    m_file.open(stream, QIODevice::WriteOnly | QIODevice::Unbuffered);
    open(QIODevice::WriteOnly | QIODevice::Unbuffered);
}

TerminalDevice::~TerminalDevice()
{
    close();
}

void TerminalDevice::close()
{
    if (!m_pending.isEmpty())
        emitEscaped(std::exchange(m_pending, {}));
    QIODevice::close();
}

qint64 TerminalDevice::writeData(const char *data, qint64 size)
{
    m_pending.append(data, size);
    const qsizetype complete = completeUtf8Prefix(m_pending);
    emitEscaped(QByteArrayView(m_pending).first(complete));
    m_pending.remove(0, complete);
    return size;
}

void TerminalDevice::emitEscaped(QByteArrayView bytes)
{
    if (bytes.isEmpty())
        return;
    const QByteArray safe = printable(bytes, LineBreaks::Keep).toUtf8();
    m_file.write(safe);
    m_file.flush();
}

} // namespace db::cli
