namespace URWPGSim2D.Tournament.Batch.Slurm;

/// <summary>The task indices of a Slurm job array as sbatch's <c>--array</c> takes them: <c>0-3</c>, <c>1,3</c>, <c>0-2,5,7-9</c>.</summary>
public static class ArraySpec
{
    /// <summary>The <c>--array</c> value of <paramref name="indices"/>.</summary>
    /// <param name="indices">Distinct indices in increasing order, at least one.</param>
    /// <returns>Runs of consecutive indices as <c>first-last</c> (<c>first</c> alone for a run of one), comma-separated.</returns>
    public static string Format(IReadOnlyList<int> indices)
    {
        var text = new StringBuilder();
        for (int i = 0; i < indices.Count;)
        {
            int j = i;
            while (j + 1 < indices.Count && indices[j + 1] == indices[j] + 1)
            {
                j++;
            }

            if (text.Length > 0)
            {
                text.Append(',');
            }

            text.Append(indices[i].ToString(CultureInfo.InvariantCulture));
            if (j > i)
            {
                text.Append('-').Append(indices[j].ToString(CultureInfo.InvariantCulture));
            }

            i = j + 1;
        }

        return text.ToString();
    }
}
