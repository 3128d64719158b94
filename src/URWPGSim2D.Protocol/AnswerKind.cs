namespace URWPGSim2D.Protocol;

/// <summary>What a <c>decisions</c> message says about a cycle.</summary>
public enum AnswerKind
{
    /// <summary>One valid decision per fish.</summary>
    Decided,

    /// <summary>The strategy threw (<c>"fault":"exception"</c>).</summary>
    Exception,

    /// <summary>The strategy missed its deadline or is still busy (<c>"fault":"timeout"</c>).</summary>
    Timeout,

    /// <summary>The strategy's answer was unusable (<c>"fault":"badAnswer"</c>), or the message itself was (wrong count, a gear outside 0..15, not JSON).</summary>
    BadAnswer,
}
