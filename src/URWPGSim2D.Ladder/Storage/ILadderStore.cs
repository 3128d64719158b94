using System;
using System.Collections.Generic;

namespace URWPGSim2D.Ladder.Storage;

/// <summary>
/// Everything the ladder keeps: settings, ladders, teams, submissions and matches. One
/// implementation per database (<see cref="SqlLadderStore"/> over SQLite or PostgreSQL); every change
/// is one transaction, so a service killed at any moment leaves each row whole.
/// </summary>
internal interface ILadderStore : IDisposable
{
    /// <summary>Brings the schema up to date (run once on start).</summary>
    void Migrate();

    /// <summary>The schema version after <see cref="Migrate"/>.</summary>
    int SchemaVersion();

    /// <summary>A setting's value, or null.</summary>
    string? Setting(string key);

    /// <summary>Sets a setting.</summary>
    void SetSetting(string key, string value);

    /// <summary>The ladder of <paramref name="item"/>, created with the given length and first seed when there is none.</summary>
    LadderRow OpenLadder(string item, int cycles, ulong firstSeed);

    /// <summary>A new ladder of <paramref name="item"/> (whether or not one of that item exists).</summary>
    LadderRow CreateLadder(string item, int cycles, ulong firstSeed);

    /// <summary>Every ladder, by id.</summary>
    IReadOnlyList<LadderRow> Ladders();

    /// <summary>The ladder with the highest id, or null when there is none.</summary>
    LadderRow? NewestLadder();

    /// <summary>A ladder by id.</summary>
    LadderRow? Ladder(long id);

    /// <summary>Pauses or resumes ranked play of a ladder.</summary>
    void SetPaused(long ladder, bool paused);

    /// <summary>Sets a ladder's match length for the matches made from now on.</summary>
    void SetCycles(long ladder, int cycles);

    /// <summary>Adds a team (a house entrant playing in <paramref name="ladder"/>; 0 for a team that submits); null when the name is taken.</summary>
    TeamRow? AddTeam(string name, string tokenHash, string? house, long ladder);

    /// <summary>Sets a team's password hash.</summary>
    void SetPassword(long team, string passwordHash);

    /// <summary>Every team, by id.</summary>
    IReadOnlyList<TeamRow> Teams();

    /// <summary>A team by its token's hash, or null.</summary>
    TeamRow? TeamByToken(string tokenHash);

    /// <summary>A team by name, or null.</summary>
    TeamRow? TeamByName(string name);

    /// <summary>Adds a sign-in session of a team (by its token's hash).</summary>
    void AddSession(long team, string tokenHash);

    /// <summary>The team of a session token's hash, or null.</summary>
    TeamRow? TeamBySession(string tokenHash);

    /// <summary>Adds a submission in state <see cref="SubmissionRow.Checking"/>; its path is filled in by <see cref="SetSubmissionPath"/>.</summary>
    SubmissionRow AddSubmission(long team, long ladder, string kind, DateTime created);

    /// <summary>Sets where a submission's files are.</summary>
    void SetSubmissionPath(long submission, string path);

    /// <summary>Keeps a submission's files and where they are, in one transaction (the files replace any kept before).</summary>
    void SetSubmissionFiles(long submission, string path, IReadOnlyList<StoredFile> files);

    /// <summary>A submission's files, by name (none when it has none).</summary>
    IReadOnlyList<StoredFile> SubmissionFiles(long submission);

    /// <summary>The submissions that have a path but no files in the database (kept by an older version in its data folder).</summary>
    IReadOnlyList<SubmissionRow> SubmissionsWithoutFiles();

    /// <summary>Ends a submission's check: <see cref="SubmissionRow.Ok"/> or <see cref="SubmissionRow.Error"/>, with its log.</summary>
    void FinishSubmission(long submission, bool ok, string log);

    /// <summary>A submission by id, or null.</summary>
    SubmissionRow? Submission(long id);

    /// <summary>A team's submissions, newest first (every team's with <paramref name="team"/> null).</summary>
    IReadOnlyList<SubmissionRow> Submissions(long? team);

    /// <summary>How many submissions a team made for a ladder since <paramref name="since"/>.</summary>
    int SubmissionsSince(long team, long ladder, DateTime since);

    /// <summary>A team's newest submission for a ladder that checked, or null.</summary>
    SubmissionRow? NewestWorking(long team, long ladder);

    /// <summary>Queues a match.</summary>
    MatchRow AddMatch(long ladder, IReadOnlyList<long> teams, IReadOnlyList<long> submissions, bool final, Func<long, ulong> seedOf);

    /// <summary>Takes the oldest queued match of the ladder (final matches first) and marks it running; null when none waits.</summary>
    MatchRow? ClaimNext(long ladder);

    /// <summary>Claims one given match (queued → running); false when it is not queued.</summary>
    bool Claim(long match);

    /// <summary>
    /// Writes a running match's record, once: in one transaction, and only while it is still
    /// running (a match re-played after a restart cannot be written twice). True when written.
    /// </summary>
    /// <param name="match">The match.</param>
    /// <param name="record">Its record.</param>
    /// <param name="files">Its output files, kept in the same transaction (none: null).</param>
    bool FinishMatch(long match, string record, IReadOnlyList<StoredFile>? files = null);

    /// <summary>The names and SHA-256 of a match's files (without their bytes), by name.</summary>
    IReadOnlyList<(string Name, string Sha256)> MatchFileHashes(long match);

    /// <summary>One file of a match, or null.</summary>
    StoredFile? MatchFile(long match, string name);

    /// <summary>Keeps a finished match's files when it has none yet (read from a data folder of an older version); false when it had some or is not finished.</summary>
    bool AddMatchFiles(long match, IReadOnlyList<StoredFile> files);

    /// <summary>The finished matches without files in the database, by id.</summary>
    IReadOnlyList<long> MatchesWithoutFiles();

    /// <summary>
    /// Claims a match for the job <paramref name="job"/> that plays it (another process's, through the
    /// job library): a queued match, or one this same job claimed before (the job run again after its
    /// worker died). False when the match is done, dropped, or another job's.
    /// </summary>
    bool ClaimForJob(long match, string job);

    /// <summary>Notes the job a queued match was handed to (when it has none yet).</summary>
    void SetJob(long match, string job);

    /// <summary>A ladder's queued matches not yet handed to a job, oldest first.</summary>
    IReadOnlyList<long> Unscheduled(long ladder);

    /// <summary>Puts every running match back in the queue (on start: what a stopped service was playing is played again from its seed).</summary>
    int RequeueRunning();

    /// <summary>Puts a finished match back in the queue, its record and files removed (the organiser's requeue); false when it is not done.</summary>
    bool Requeue(long match);

    /// <summary>A match by id, or null.</summary>
    MatchRow? Match(long id);

    /// <summary>A ladder's matches in the given states, newest first, at most <paramref name="limit"/>.</summary>
    IReadOnlyList<MatchRow> Matches(long ladder, IReadOnlyCollection<string> states, int limit);

    /// <summary>Every finished match's record of a ladder, by id.</summary>
    IReadOnlyList<(long Id, string Record, bool Final)> Records(long ladder);

    /// <summary>Per team, matches of the ladder played, running or queued (teams without any are absent).</summary>
    IReadOnlyDictionary<long, int> Games(long ladder);

    /// <summary>
    /// Starts a ladder's final round, in one transaction: the queued ranked matches are dropped (ranked
    /// play stops) and the final's matches queued, each side's team and submission as given. False, with
    /// nothing changed, when the ladder has a final round already.
    /// </summary>
    bool StartFinal(long ladder, IReadOnlyList<(long TeamA, long TeamB, long SubA, long SubB)> matches, Func<long, ulong> seedOf);

    /// <summary>A ladder's final-round matches, by id (none before its final round starts).</summary>
    IReadOnlyList<MatchRow> FinalMatches(long ladder);
}
