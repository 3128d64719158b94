using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using System.Text;

namespace URWPGSim2D.Learning;

/// <summary>
/// The C interface of the native library (include/urwpgsim2d.h): a <see cref="MatchBatch"/> behind
/// an opaque handle. Every function returns 0 on success or an error code; the message of the last
/// error on the calling thread is <c>urw_last_error()</c>. Nothing a caller passes crashes the
/// process: bad arguments, bad handles and unexpected exceptions all come back as codes.
/// </summary>
internal static unsafe class NativeExports
{
    private const int Ok = 0;
    private const int BadArgument = 1;
    private const int BadHandle = 2;
    private const int BadState = 3;
    private const int Failure = 4;

    [ThreadStatic]
    private static byte* _lastError;

    [UnmanagedCallersOnly(EntryPoint = "urw_last_error")]
    public static byte* LastError() => _lastError != null ? _lastError : (byte*)Unsafe.AsPointer(ref MemoryMarshal.GetReference("\0"u8));

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_create")]
    public static int Create(byte* item, byte* opponent, int count, int team, int cycles, IntPtr* handle)
    {
        try
        {
            if (handle == null)
            {
                return Fail(BadArgument, "handle: null pointer");
            }

            *handle = IntPtr.Zero;
            if (item == null || opponent == null)
            {
                return Fail(BadArgument, item == null ? "item: null pointer" : "opponent: null pointer");
            }

            var batch = new MatchBatch(Utf8(item), Utf8(opponent), count, team, cycles);
            *handle = GCHandle.ToIntPtr(GCHandle.Alloc(batch));
            return Ok;
        }
        catch (Exception e)
        {
            return Fail(e);
        }
    }

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_destroy")]
    public static void Destroy(IntPtr handle)
    {
        try
        {
            if (handle != IntPtr.Zero)
            {
                GCHandle.FromIntPtr(handle).Free();
            }
        }
        catch (InvalidOperationException)
        {
            // Destroyed already: nothing to do.
        }
    }

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_sizes")]
    public static int Sizes(IntPtr handle, int* count, int* observationSize, int* actionSize, int* teamFish)
    {
        try
        {
            var batch = Of(handle);
            if (batch is null)
            {
                return Fail(BadHandle, "handle: not a batch (null, or destroyed)");
            }

            if (count != null)
            {
                *count = batch.Count;
            }

            if (observationSize != null)
            {
                *observationSize = batch.ObservationSize;
            }

            if (actionSize != null)
            {
                *actionSize = batch.ActionSize;
            }

            if (teamFish != null)
            {
                *teamFish = batch.TeamFish;
            }

            return Ok;
        }
        catch (Exception e)
        {
            return Fail(e);
        }
    }

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_reset")]
    public static int Reset(IntPtr handle, ulong* seeds, long seedsLength, int maxSteps, float* observations, long observationsLength)
    {
        try
        {
            var batch = Of(handle);
            if (batch is null)
            {
                return Fail(BadHandle, "handle: not a batch (null, or destroyed)");
            }

            batch.Reset(Span(seeds, seedsLength, nameof(seeds)), Span(observations, observationsLength, nameof(observations)), maxSteps);
            return Ok;
        }
        catch (Exception e)
        {
            return Fail(e);
        }
    }

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_step")]
    public static int Step(IntPtr handle, int* actions, long actionsLength, float* observations, long observationsLength, float* rewards, byte* terminated, byte* truncated, long count)
    {
        try
        {
            var batch = Of(handle);
            if (batch is null)
            {
                return Fail(BadHandle, "handle: not a batch (null, or destroyed)");
            }

            batch.Step(
                Span(actions, actionsLength, nameof(actions)),
                Span(observations, observationsLength, nameof(observations)),
                Span(rewards, count, nameof(rewards)),
                Span((bool*)terminated, count, nameof(terminated)),
                Span((bool*)truncated, count, nameof(truncated)));
            return Ok;
        }
        catch (Exception e)
        {
            return Fail(e);
        }
    }

    [UnmanagedCallersOnly(EntryPoint = "urw_batch_info")]
    public static int Info(IntPtr handle, int* cycles, int* goals, ulong* seeds, long count)
    {
        try
        {
            var batch = Of(handle);
            if (batch is null)
            {
                return Fail(BadHandle, "handle: not a batch (null, or destroyed)");
            }

            batch.Info(Span(cycles, count, nameof(cycles)), Span(goals, 2 * count, nameof(goals)), Span(seeds, count, nameof(seeds)));
            return Ok;
        }
        catch (Exception e)
        {
            return Fail(e);
        }
    }

    private static MatchBatch? Of(IntPtr handle)
    {
        if (handle == IntPtr.Zero)
        {
            return null;
        }

        return GCHandle.FromIntPtr(handle).Target as MatchBatch;
    }

    private static Span<T> Span<T>(T* pointer, long length, string name)
        where T : unmanaged
    {
        if (length < 0 || length > int.MaxValue)
        {
            throw new ArgumentException($"{name}: length {length}, expected 0 to {int.MaxValue}", name);
        }

        if (pointer == null && length > 0)
        {
            throw new ArgumentException($"{name}: null pointer with length {length}", name);
        }

        return new Span<T>(pointer, (int)length);
    }

    private static string Utf8(byte* text) => Marshal.PtrToStringUTF8((IntPtr)text) ?? string.Empty;

    private static int Fail(Exception e) => e switch
    {
        ArgumentException a => Fail(BadArgument, a.ParamName is { } p ? a.Message.Replace($" (Parameter '{p}')", string.Empty, StringComparison.Ordinal) : a.Message),
        InvalidOperationException => Fail(BadState, e.Message),
        _ => Fail(Failure, $"{e.GetType().Name}: {e.Message}"),
    };

    private static int Fail(int code, string message)
    {
        if (_lastError != null)
        {
            NativeMemory.Free(_lastError);
        }

        int length = Encoding.UTF8.GetByteCount(message);
        _lastError = (byte*)NativeMemory.Alloc((nuint)length + 1);
        Encoding.UTF8.GetBytes(message, new Span<byte>(_lastError, length));
        _lastError[length] = 0;
        return code;
    }
}
