namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>The time bank's arithmetic, case by case and against a plain re-count of random calls.</summary>
public sealed class TimeBankTests
{
    private static TimeSpan Ms(double ms) => TimeSpan.FromMilliseconds(ms);

    [Fact]
    public void The_default_bank_is_a_tenth_of_the_matchs_deadlines_and_at_least_five_seconds()
    {
        Assert.Equal(TimeSpan.FromSeconds(60), TimeBank.DefaultFor(6000, 100));
        Assert.Equal(TimeSpan.FromSeconds(6), TimeBank.DefaultFor(600, 100));
        Assert.Equal(TimeSpan.FromSeconds(5), TimeBank.DefaultFor(100, 100));
        Assert.Equal(TimeSpan.FromSeconds(5), TimeBank.DefaultFor(0, 100));
    }

    [Fact]
    public void The_call_limit_is_a_hundred_deadlines_and_at_least_ten_seconds()
    {
        Assert.Equal(TimeSpan.FromSeconds(10), TimeBank.CallLimitFor(Ms(20)));
        Assert.Equal(TimeSpan.FromSeconds(30), TimeBank.CallLimitFor(Ms(300)));
    }

    [Fact]
    public void The_first_call_is_allowed_the_hang_limit_and_later_calls_the_deadline()
    {
        var bank = new TimeBank(Ms(100), TimeSpan.FromSeconds(1));
        Assert.Equal(TimeSpan.FromSeconds(1), bank.CpuAllowance);
        Assert.Equal(TimeSpan.FromSeconds(2), bank.WallAllowance);
        Assert.Equal(TimeSpan.FromSeconds(5), bank.WaitLimit); // 2 × (1 s + 1 s) + 1 s
        Assert.True(bank.Charge(Ms(900), Ms(1900)));
        Assert.Equal(0, bank.LateCalls);
        Assert.Equal(Ms(100), bank.CpuAllowance);
        Assert.Equal(Ms(200), bank.WallAllowance);
        Assert.Equal(Ms(3200), bank.WaitLimit); // 2 × (100 ms + 1 s) + 1 s
        Assert.Equal(Ms(1100), bank.CpuLimit);
    }

    [Fact]
    public void A_call_pays_the_larger_of_its_cpu_overrun_and_its_wall_overrun()
    {
        var bank = new TimeBank(Ms(100), TimeSpan.FromSeconds(10));
        Assert.True(bank.Charge(Ms(10), Ms(20))); // the first call

        Assert.True(bank.Charge(Ms(150), Ms(160)));   // computes 50 ms too long
        Assert.Equal(Ms(50), bank.Used);
        Assert.True(bank.Charge(Ms(150), Ms(290)));   // a busy machine: within twice its CPU time, not charged for it
        Assert.Equal(Ms(100), bank.Used);
        Assert.True(bank.Charge(Ms(150), Ms(400)));   // 100 ms beyond twice its CPU time
        Assert.Equal(Ms(200), bank.Used);
        Assert.True(bank.Charge(Ms(1), Ms(950)));     // sleeps: 750 ms beyond twice the deadline
        Assert.Equal(Ms(950), bank.Used);
        Assert.True(bank.Charge(null, Ms(450)));      // CPU time not measured: wall time alone
        Assert.Equal(Ms(1200), bank.Used);
        Assert.True(bank.Charge(Ms(100), Ms(200)));   // exactly at the deadline: free
        Assert.Equal(5, bank.LateCalls);
        Assert.Equal(Ms(950), bank.Slowest);
        Assert.False(bank.Spent);
    }

    [Fact]
    public void Time_spent_waiting_for_a_cpu_is_not_the_calls()
    {
        var bank = new TimeBank(Ms(100), TimeSpan.FromSeconds(10));
        Assert.True(bank.Charge(Ms(10), Ms(20))); // the first call

        // 300 ms of computing that took 2 s on a busy machine, 1.7 s of it waiting for a core: 200 ms over the deadline only.
        Assert.True(bank.Charge(Ms(300), Ms(2000), Ms(1700)));
        Assert.Equal(Ms(200), bank.Used);

        // Unmeasured waiting: the wall time counts, beyond twice the call's CPU time.
        Assert.True(bank.Charge(Ms(300), Ms(2000)));
        Assert.Equal(Ms(200 + 1400), bank.Used);

        // A sleeper waits for nothing: its sleep is charged whatever the machine does.
        Assert.True(bank.Charge(Ms(1), Ms(950), TimeSpan.Zero));
        Assert.Equal(Ms(200 + 1400 + 750), bank.Used);
    }

    [Fact]
    public void A_call_that_needs_more_than_is_left_spends_the_bank()
    {
        var bank = new TimeBank(Ms(100), Ms(300));
        Assert.True(bank.Charge(Ms(10), Ms(10)));
        Assert.True(bank.Charge(Ms(400), Ms(400)));
        Assert.Equal(TimeSpan.Zero, bank.Remaining);
        Assert.False(bank.Spent);
        Assert.False(bank.Charge(Ms(101), Ms(101)));
        Assert.True(bank.Spent);
        Assert.Equal(TimeSpan.Zero, bank.Remaining);
        Assert.Equal(Ms(300), bank.Used);
    }

    [Fact]
    public void Waiting_stops_at_the_call_limit_however_much_is_banked()
    {
        var bank = new TimeBank(Ms(100), TimeSpan.FromSeconds(100));
        bank.Charge(Ms(1), Ms(1));
        Assert.Equal(TimeSpan.FromSeconds(10), bank.WaitLimit);
        Assert.True(bank.WaitEndsAtCallLimit);
        Assert.False(new TimeBank(Ms(100), TimeSpan.FromSeconds(2)).WaitEndsAtCallLimit); // 2 × (1 s + 2 s) + 2 s = 8 s, under 10 s
        Assert.True(new TimeBank(Ms(100), TimeSpan.FromSeconds(3)).WaitEndsAtCallLimit);  // 2 × (1 s + 3 s) + 3 s = 11 s
        bank.GiveUp(bank.WaitLimit);
        Assert.True(bank.Spent);
        Assert.Equal(TimeSpan.FromSeconds(10), bank.Slowest);
    }

    [Fact]
    public void A_hosts_group_measures_its_cpu_time_and_its_waits_for_a_cpu()
    {
        var group = SandboxCgroup.Create(256L << 20, 64, out string? problem);
        Assert.True(group is not null, "CI runs where control groups can be made: " + problem);
        using (group)
        {
            Assert.NotNull(group.CpuTime());
            Assert.True(group.WaitingTime() is not null, "this kernel gives pressure stall information (cpu.pressure) in a group of the unified hierarchy");
        }
    }

    [Fact]
    public void Bad_settings_are_refused_naming_the_value()
    {
        Assert.Equal("deadline: must be positive, got 0 ms (Parameter 'deadline')", Assert.Throws<ArgumentException>(() => new TimeBank(TimeSpan.Zero, Ms(1))).Message);
        Assert.Equal("reserve: must not be negative, got -1 s (Parameter 'reserve')", Assert.Throws<ArgumentException>(() => new TimeBank(Ms(1), TimeSpan.FromSeconds(-1))).Message);
    }

    [Fact]
    public void Random_calls_are_charged_as_a_plain_recount_says()
    {
        const long PerMs = TimeSpan.TicksPerMillisecond;
        var random = new Random(20261205);
        for (int round = 0; round < 200; round++)
        {
            long deadline = random.Next(1, 300) * PerMs, reserve = random.Next(0, 5000) * PerMs;
            var bank = new TimeBank(TimeSpan.FromTicks(deadline), TimeSpan.FromTicks(reserve));
            long left = reserve;
            bool first = true, spent = false;
            int late = 0;
            for (int call = 0; call < 50 && !spent; call++)
            {
                long cpu = random.NextInt64(0, deadline * 2), wall = cpu + random.NextInt64(0, (deadline * 3) + 1);
                bool cpuKnown = random.Next(4) > 0;
                long allowance = first ? Math.Max(1000 * PerMs, deadline * 10) : deadline;
                long computing = cpuKnown ? cpu : 0;
                long overrun = Math.Max(computing - allowance, wall - (2 * Math.Max(allowance, computing)));
                first = false;
                bool expected = true;
                if (overrun > 0)
                {
                    late++;
                    if (overrun > left)
                    {
                        spent = true;
                        expected = false;
                        left = 0;
                    }
                    else
                    {
                        left -= overrun;
                    }
                }

                Assert.Equal(expected, bank.Charge(cpuKnown ? TimeSpan.FromTicks(cpu) : null, TimeSpan.FromTicks(wall)));
                Assert.Equal(left, bank.Remaining.Ticks);
            }

            Assert.Equal(late, bank.LateCalls);
            Assert.Equal(spent, bank.Spent);
            Assert.Equal(reserve - left, bank.Used.Ticks);
        }
    }
}
