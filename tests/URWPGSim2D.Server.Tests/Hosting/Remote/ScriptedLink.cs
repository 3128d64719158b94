namespace URWPGSim2D.Server.Tests.Hosting.Remote;

/// <summary>
/// A strategy link that plays a script: what the client "sends" is queued bytes, a <see cref="Late"/>
/// entry makes the read under way run out of time (as a TCP read past the deadline does), and the
/// end of the script is the client going away. What the server writes is kept, line by line.
/// </summary>
internal sealed class ScriptedLink : IStrategyLink
{
    private readonly Queue<object> _script = new();
    private readonly ScriptStream _from;
    private readonly MemoryStream _to = new();

    public ScriptedLink(bool survivesLateAnswer = true)
    {
        SurvivesLateAnswer = survivesLateAnswer;
        _from = new ScriptStream(this);
    }

    /// <summary>A script entry: the read waiting now runs out of time.</summary>
    public static object Late { get; } = new();

    public Stream FromClient => _from;

    public Stream ToClient => _to;

    public bool SurvivesLateAnswer { get; }

    public bool CutByWait => false;

    public TimeSpan? CpuTime() => null;

    public TimeSpan? WaitingTime() => null;

    public long? PeakMemoryBytes() => null;

    public bool Waiting { get; private set; }

    public bool Aborted { get; private set; }

    /// <summary>The lines the server wrote.</summary>
    public string[] Written => Encoding.UTF8.GetString(_to.ToArray()).Split('\n', StringSplitOptions.RemoveEmptyEntries);

    public ScriptedLink Send(string text) => Send(Encoding.UTF8.GetBytes(text));

    public ScriptedLink Send(byte[] bytes)
    {
        _script.Enqueue(bytes);
        return this;
    }

    public ScriptedLink RunLate()
    {
        _script.Enqueue(Late);
        return this;
    }

    public void BeginWait(TimeSpan limit) => Waiting = true;

    public void EndWait() => Waiting = false;

    public void Abort()
    {
        Aborted = true;
        _script.Clear();
    }

    public void Finish(int ms)
    {
    }

    public string Ending() => "the scripted client went away";

    public void Dispose()
    {
    }

    private sealed class ScriptStream(ScriptedLink link) : Stream
    {
        private byte[] _current = [];
        private int _at;

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => false;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override int Read(byte[] buffer, int offset, int count)
        {
            while (_at == _current.Length)
            {
                if (!link._script.TryDequeue(out var next))
                {
                    return 0;
                }

                if (ReferenceEquals(next, Late))
                {
                    if (!link.Waiting)
                    {
                        throw new InvalidOperationException("the script runs late where the server does not wait");
                    }

                    throw new TimeoutException("scripted: late");
                }

                _current = (byte[])next;
                _at = 0;
            }

            int n = Math.Min(count, _current.Length - _at);
            Array.Copy(_current, _at, buffer, offset, n);
            _at += n;
            return n;
        }

        public override void Flush()
        {
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
