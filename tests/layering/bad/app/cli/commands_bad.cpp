void run(db::DeviceConnection *connection)
{
    const auto *node = dynamic_cast<const db::canopen::CanopenConnection *>(connection);
    (void)node;
}
