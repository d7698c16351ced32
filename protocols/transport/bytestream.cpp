#include "bytestream.h"

namespace db {

void ByteStream::open()
{
    if (m_state != State::Closed)
        return;
    m_state = State::Opening;
    doOpen();
}

void ByteStream::close()
{
    if (m_state == State::Closed || m_state == State::Closing)
        return;
    m_state = State::Closing;
    doClose();
}

bool ByteStream::write(const QByteArray &bytes)
{
    if (m_state != State::Open)
        return false;
    doWrite(bytes);
    return true;
}

void ByteStream::setOpened()
{
    if (m_state != State::Opening)
        return;
    m_state = State::Open;
    Q_EMIT opened();
}

void ByteStream::setClosed(const Error &error)
{
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    Q_EMIT closed(error);
}

void ByteStream::deliver(const QByteArray &bytes)
{
    if (m_state == State::Open && !bytes.isEmpty())
        Q_EMIT received(bytes);
}

} // namespace db
