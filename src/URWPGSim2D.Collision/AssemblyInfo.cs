// Stack buffers in the narrow phase are always written before they are read: skip zeroing them.
[module: SkipLocalsInit]
