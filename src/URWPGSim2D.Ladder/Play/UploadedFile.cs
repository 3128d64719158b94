namespace URWPGSim2D.Ladder.Play;

/// <summary>One file of an upload: its name as the client gave it and its bytes.</summary>
internal sealed record UploadedFile(string Name, byte[] Bytes);
