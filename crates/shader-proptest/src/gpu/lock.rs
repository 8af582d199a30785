//! The one way the device side locks a mutex, for the parts that share one (the device, its
//! submissions, a kernel's buffers).

/// Locks `mutex`, whose data stays valid if a holder panicked: the device's validation messages
/// (a panic elsewhere must not lose them), its submitters and queues, and a kernel's buffers.
pub(crate) fn lock<T>(mutex: &std::sync::Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}
