using System.Text;

namespace URWPGSim2D.Protocol;

/// <summary>What a client's strategy printed in one cycle as a <c>decisions</c> message carries it: the kept text (<c>log</c>) and the characters dropped past the client's bound (<c>logDropped</c>).</summary>
public sealed class PrintedOutput
{
    /// <summary>The kept text.</summary>
    public StringBuilder Text { get; } = new();

    /// <summary>Characters the client dropped.</summary>
    public int Dropped { get; set; }

    /// <summary>Forgets the last message's output.</summary>
    public void Clear()
    {
        Text.Clear();
        Dropped = 0;
    }
}
