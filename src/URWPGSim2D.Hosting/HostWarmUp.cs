using System.Diagnostics.CodeAnalysis;
using System.Runtime.InteropServices;
using URWPGSim2D.Protocol;
using URWPGSim2D.Engine.BuiltInStrategies;

namespace URWPGSim2D.Hosting;

/// <summary>
/// What a waiting strategy host (<c>host -</c>, <see cref="HostPool"/>) does before it has a strategy:
/// it runs the code a strategy's start runs (loading an assembly through the strategy loader, the
/// protocol's hello, assignment, one cycle and its answer on the thread that reads it, with a built-in
/// strategy over streams in memory) so the JIT has compiled it, then reads its strategy's line,
/// <c>CPU-SECONDS SPEC</c>, limits its CPU time to it and goes on as <c>host SPEC</c>.
/// </summary>
public static partial class HostWarmUp
{
    private const int LineLimit = 4096;

    /// <summary>Plays one cycle of a built-in strategy over the protocol in memory and loads an assembly as a strategy's is loaded; whatever fails here is ignored.</summary>
    [UnconditionalSuppressMessage("SingleFile", "IL3000", Justification = "The server runs from its own folder (never a single-file bundle): assemblies have paths.")]
    public static void Run()
    {
        try
        {
            var writer = new MessageWriter();
            var assignment = new AssignmentMessage(ProtocolVersion.Current, 0, string.Empty, "warm-up", [0, 1], 4, 9, 100, 100, 3000, 2000, []);
            var input = new MemoryStream();
            input.Write(writer.Assignment(assignment));
            input.Write(writer.Cycle(assignment.CreateSnapshot()));
            input.Write(writer.End(new EndMessage(1, [0, 0], 0)));
            input.Position = 0;
            var output = new MemoryStream();
            new StrategyClient(input, output).Play(new ChaseBallStrategy(), null);
            var decisions = new Strategies.Decision[2];
            foreach (var line in Encoding.UTF8.GetString(output.ToArray()).Split('\n', StringSplitOptions.RemoveEmptyEntries))
            {
                byte[] bytes = Encoding.UTF8.GetBytes(line);
                _ = MessageReader.TypeOf(bytes) == MessageType.Decisions ? MessageReader.ReadDecisions(bytes, 0, decisions, out _) : default;
            }
        }
        catch (Exception e) when (e is ProtocolException or IOException or InvalidOperationException or ArgumentException)
        {
            // a warm-up only
        }

        string sdk = typeof(IStrategy).Assembly.Location;
        var context = new StrategyLoadContext("warm-up", sdk);
        try
        {
            StrategyResolver.FindType(Compat.Retargeting.OriginalAssemblyLoader.Load(context, sdk), sdk, null);
        }
        catch (Exception e) when (e is StrategyLoadException or IOException or BadImageFormatException or InvalidOperationException)
        {
            // the SDK holds no strategy: the loader's code has run all the same
        }
        finally
        {
            context.Unload();
        }
    }

    /// <summary>Reads the line <c>CPU-SECONDS SPEC</c> from <paramref name="fromServer"/> (byte by byte: the protocol reads the rest) and limits this process's CPU time to it (SIGXCPU then; SIGKILL a second later).</summary>
    /// <returns>The SPEC, or null when the server closed the stream or sent something else.</returns>
    public static string? ReadStrategy(Stream fromServer)
    {
        var line = new MemoryStream();
        int b;
        while ((b = fromServer.ReadByte()) >= 0 && b != '\n')
        {
            if (line.Length >= LineLimit)
            {
                return null;
            }

            line.WriteByte((byte)b);
        }

        string text = Encoding.UTF8.GetString(line.ToArray());
        int space = text.IndexOf(' ', StringComparison.Ordinal);
        if (b < 0 || space <= 0 || !int.TryParse(text.AsSpan(0, space), NumberStyles.None, CultureInfo.InvariantCulture, out int cpuSeconds))
        {
            return null;
        }

        if (OperatingSystem.IsLinux())
        {
            // As prlimit sets a host's (SandboxCommand.Limits): SIGXCPU at the limit, which ends the host
            // and says why; SIGKILL a second later only where the strategy holds SIGXCPU off.
            var limit = new Limit { Current = (ulong)cpuSeconds, Maximum = (ulong)cpuSeconds + 1 };
            _ = SetLimit(CpuTime, ref limit); // lowering a limit is always allowed
        }

        return text[(space + 1)..];
    }

    private const int CpuTime = 0; // RLIMIT_CPU

    [LibraryImport("libc", EntryPoint = "setrlimit", SetLastError = true)]
    private static partial int SetLimit(int resource, ref Limit limit);

    [StructLayout(LayoutKind.Sequential)]
    private struct Limit
    {
        public ulong Current;
        public ulong Maximum;
    }
}
