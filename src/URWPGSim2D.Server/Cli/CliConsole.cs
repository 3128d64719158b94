namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The three standard streams a command talks to. The process passes the real console;
/// tests pass in-memory readers and writers.
/// </summary>
/// <param name="In">Standard input (read when a command is given <c>-</c> as its file).</param>
/// <param name="Out">Standard output: written only once a command has its whole result.</param>
/// <param name="Error">Standard error: usage text and one-line error messages.</param>
internal sealed record CliConsole(TextReader In, TextWriter Out, TextWriter Error)
{
    /// <summary>Writes one error line to <see cref="Error"/>, escaping whatever would break it (<see cref="MessageText.Escape"/>).</summary>
    /// <param name="line">The message; user text echoed in it may hold anything.</param>
    public void ErrorLine(string line) => Error.WriteLine(MessageText.Escape(line));
}
